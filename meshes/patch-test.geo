// The classical distorted five-element patch (MacNeal and Harder): a
// rectangle whose four interior nodes form a skewed inner quadrilateral.
// Any linear displacement field must be reproduced exactly on it.
//
// Physical groups:
//   surface 1 "patch"     all five elements
//   curve   1 "boundary"  the whole outer boundary
DefineConstant[
  width  = {0.24, Name "Parameters/width"},
  height = {0.12, Name "Parameters/height"}
];

Point(1) = {0, 0, 0};
Point(2) = {width, 0, 0};
Point(3) = {width, height, 0};
Point(4) = {0, height, 0};
// Interior nodes as in MacNeal and Harder's patch, scaled to the rectangle.
Point(5) = {0.04 / 0.24 * width, 0.02 / 0.12 * height, 0};
Point(6) = {0.18 / 0.24 * width, 0.03 / 0.12 * height, 0};
Point(7) = {0.16 / 0.24 * width, 0.08 / 0.12 * height, 0};
Point(8) = {0.08 / 0.24 * width, 0.08 / 0.12 * height, 0};

Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 8}; Line(8) = {8, 5};
Line(9) = {1, 5}; Line(10) = {2, 6}; Line(11) = {3, 7}; Line(12) = {4, 8};

Curve Loop(1) = {1, 10, -5, -9};  Plane Surface(1) = {1};  // bottom
Curve Loop(2) = {2, 11, -6, -10}; Plane Surface(2) = {2};  // right
Curve Loop(3) = {3, 12, -7, -11}; Plane Surface(3) = {3};  // top
Curve Loop(4) = {4, 9, -8, -12};  Plane Surface(4) = {4};  // left
Curve Loop(5) = {5, 6, 7, 8};     Plane Surface(5) = {5};  // centre

Transfinite Curve{:} = 2;
Transfinite Surface{1, 2, 3, 4, 5};
Recombine Surface{1, 2, 3, 4, 5};

Physical Surface("patch", 1) = {1, 2, 3, 4, 5};
Physical Curve("boundary", 1) = {1, 2, 3, 4};
