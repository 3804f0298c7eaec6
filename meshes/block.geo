// A rectangular block of structured quadrilaterals.
//
// Parameters:
//   width, height      size of the block
//   x0, y0             its lower-left corner (default the origin)
//   nx, ny             elements along the width and the height
//
// Physical groups:
//   surface 1 "block"
//   curves  1 "bottom", 2 "right", 3 "top", 4 "left"
DefineConstant[
  width  = {1, Name "Parameters/width"},
  height = {1, Name "Parameters/height"},
  nx     = {4, Name "Parameters/nx"},
  ny     = {4, Name "Parameters/ny"},
  x0     = {0, Name "Parameters/x0"},
  y0     = {0, Name "Parameters/y0"}
];

Point(1) = {x0, y0, 0};
Point(2) = {x0 + width, y0, 0};
Point(3) = {x0 + width, y0 + height, 0};
Point(4) = {x0, y0 + height, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 3} = nx + 1;
Transfinite Curve{2, 4} = ny + 1;
Transfinite Surface{1};
Recombine Surface{1};

Physical Surface("block", 1) = {1};
Physical Curve("bottom", 1) = {1};
Physical Curve("right", 2) = {2};
Physical Curve("top", 3) = {3};
Physical Curve("left", 4) = {4};
