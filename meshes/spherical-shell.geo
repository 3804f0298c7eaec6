// The r-z plane of a thick spherical shell (x = r >= 0, y = z the axis),
// for Fourier kinematics: the half annulus a <= rho <= b between -90 and
// 90 degrees, its circles drawn as gmsh arcs (two quarters each), so that
// the cells along them follow the sphere (Mesh/Curved cells).
//
// Parameters:
//   inner     a
//   outer     b
//   n_around  elements along each quarter circle
//   n_radial  elements from a to b
//
// Physical groups:
//   surface 1 "shell"
//   curves  1 "inside" (rho = a), 2 "outside" (rho = b), 3 "axis" (x = 0)
DefineConstant[
  inner    = {1, Name "Parameters/inner"},
  outer    = {2, Name "Parameters/outer"},
  n_around = {4, Name "Parameters/n_around"},
  n_radial = {4, Name "Parameters/n_radial"}
];

Point(1) = {0, 0, 0};
Point(2) = {0, -inner, 0};  Point(3) = {inner, 0, 0};  Point(4) = {0, inner, 0};
Point(5) = {0, -outer, 0};  Point(6) = {outer, 0, 0};  Point(7) = {0, outer, 0};

Circle(1) = {2, 1, 3};  Circle(2) = {3, 1, 4};     // inside
Circle(3) = {5, 1, 6};  Circle(4) = {6, 1, 7};     // outside
Line(5) = {2, 5};  Line(6) = {3, 6};  Line(7) = {4, 7};   // radial

Curve Loop(1) = {5, 3, -6, -1};  Plane Surface(1) = {1};
Curve Loop(2) = {6, 4, -7, -2};  Plane Surface(2) = {2};

Transfinite Curve{1, 2, 3, 4} = n_around + 1;
Transfinite Curve{5, 6, 7} = n_radial + 1;
Transfinite Surface{1, 2};
Recombine Surface{1, 2};

Physical Surface("shell", 1) = {1, 2};
Physical Curve("inside", 1) = {1, 2};
Physical Curve("outside", 2) = {3, 4};
Physical Curve("axis", 3) = {5, 7};
