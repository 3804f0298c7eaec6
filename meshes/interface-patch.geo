// Two blocks, one on the other, joined along a physical curve that carries
// zero-thickness interface elements: the patch test of those elements.
//
// Parameters:
//   length   L, the width of both blocks and the length of the interface
//   height   h, the height of each block
//   nx, ny   elements along the interface and up each block
//   x0       x of the left side (off the axis when revolved)
//
// Physical groups:
//   surface 1 "blocks"
//   curves  1 "bottom" (y = -h), 2 "top" (y = h), 3 "interface" (y = 0),
//           4 "left" (x = x0, both blocks), 5 "right" (x = x0 + L)
DefineConstant[
  length = {1, Name "Parameters/length"},
  height = {0.5, Name "Parameters/height"},
  nx     = {4, Name "Parameters/nx"},
  ny     = {2, Name "Parameters/ny"},
  x0     = {0, Name "Parameters/x0"}
];

Point(1) = {x0, -height, 0};
Point(2) = {x0 + length, -height, 0};
Point(3) = {x0 + length, 0, 0};
Point(4) = {x0, 0, 0};
Point(5) = {x0 + length, height, 0};
Point(6) = {x0, height, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {4, 3};
Line(4) = {1, 4};
Line(5) = {3, 5};
Line(6) = {6, 5};
Line(7) = {4, 6};
Curve Loop(1) = {1, 2, -3, -4};
Plane Surface(1) = {1};
Curve Loop(2) = {3, 5, -6, -7};
Plane Surface(2) = {2};
Transfinite Curve{1, 3, 6} = nx + 1;
Transfinite Curve{2, 4, 5, 7} = ny + 1;
Transfinite Surface{1, 2};
Recombine Surface{1, 2};

Physical Surface("blocks", 1) = {1, 2};
Physical Curve("bottom", 1) = {1};
Physical Curve("top", 2) = {6};
Physical Curve("interface", 3) = {3};
Physical Curve("left", 4) = {4, 7};
Physical Curve("right", 5) = {2, 5};
