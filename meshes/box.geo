// A box of structured hexahedra: the rectangle of block.geo extruded along
// z.
//
// Parameters:
//   width, height, depth   size of the box along x, y and z
//   nx, ny, nz             elements along x, y and z
//
// Physical groups:
//   volume   1 "box"
//   surfaces 1 "bottom" (y = 0), 2 "right" (x = width), 3 "top"
//            (y = height), 4 "left" (x = 0), 5 "back" (z = 0), 6 "front"
//            (z = depth)
DefineConstant[
  width  = {1, Name "Parameters/width"},
  height = {1, Name "Parameters/height"},
  depth  = {1, Name "Parameters/depth"},
  nx     = {2, Name "Parameters/nx"},
  ny     = {2, Name "Parameters/ny"},
  nz     = {2, Name "Parameters/nz"}
];

Point(1) = {0, 0, 0};
Point(2) = {width, 0, 0};
Point(3) = {width, height, 0};
Point(4) = {0, height, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 3} = nx + 1;
Transfinite Curve{2, 4} = ny + 1;
Transfinite Surface{1};
Recombine Surface{1};

// out[0] the far face, out[1] the volume, out[2..5] the faces swept by
// lines 1 to 4.
out[] = Extrude {0, 0, depth} { Surface{1}; Layers{nz}; Recombine; };

Physical Volume("box", 1) = {out[1]};
Physical Surface("bottom", 1) = {out[2]};
Physical Surface("right", 2) = {out[3]};
Physical Surface("top", 3) = {out[4]};
Physical Surface("left", 4) = {out[5]};
Physical Surface("back", 5) = {1};
Physical Surface("front", 6) = {out[0]};
