// A rigid circular inclusion (a pile's cross-section far below the ground)
// moving along x through soil, in plane strain: the half y >= 0 of the
// plane, symmetric about the x axis. Around the hole of radius R runs a
// thin annulus of width t (the contact: a thin layer of its own material,
// or with zero_thickness = 1 the pile's skin, joined to the soil by
// zero-thickness interface elements on its outer circle), then the soil
// out to the radius W, its rings graded outwards.
//
// Every circle is drawn as gmsh circular arcs (two quarters), so that the
// cells along them follow the circle (Mesh/Curved cells): the contact
// slides on a circle, not on the polygon of its nodes.
//
// Parameters:
//   radius         R
//   thickness      t, the annulus's width
//   outer          W, the soil's outer radius
//   n_around       elements along each quarter circle
//   n_radial       elements from R + t to W
//   growth         ratio of neighbouring ring widths outwards
//   zero_thickness 1: the annulus is the pile's skin (material 2) and
//                  its outer circle a physical curve (4) for interface
//                  elements
//
// Physical groups:
//   surfaces 1 "soil", 2 "contact layer" (or "pile skin")
//   curves   1 "pile" (r = R), 2 "axis of symmetry" (y = 0), 3 "outer"
//            (r = W); zero_thickness: 4 "contact" (r = R + t)
DefineConstant[
  radius         = {1, Name "Parameters/radius"},
  thickness      = {0.02, Name "Parameters/thickness"},
  outer          = {20, Name "Parameters/outer"},
  n_around       = {12, Name "Parameters/n_around"},
  n_radial       = {20, Name "Parameters/n_radial"},
  growth         = {1.2, Name "Parameters/growth"},
  zero_thickness = {0, Name "Parameters/zero_thickness"}
];

R = radius;
S = radius + thickness;
W = outer;

Point(1) = {0, 0, 0};
// Three rings of points at 0, 90 and 180 degrees.
Point(2) = {R, 0, 0};  Point(3) = {0, R, 0};  Point(4) = {-R, 0, 0};
Point(5) = {S, 0, 0};  Point(6) = {0, S, 0};  Point(7) = {-S, 0, 0};
Point(8) = {W, 0, 0};  Point(9) = {0, W, 0};  Point(10) = {-W, 0, 0};

Circle(1) = {2, 1, 3};   Circle(2) = {3, 1, 4};     // the pile
Circle(3) = {5, 1, 6};   Circle(4) = {6, 1, 7};     // the contact's outside
Circle(5) = {8, 1, 9};   Circle(6) = {9, 1, 10};    // outer
// Radial lines, outwards.
Line(7) = {2, 5};   Line(8) = {3, 6};   Line(9) = {4, 7};     // across t
Line(10) = {5, 8};  Line(11) = {6, 9};  Line(12) = {7, 10};   // the soil

Curve Loop(1) = {7, 3, -8, -1};    Plane Surface(1) = {1};
Curve Loop(2) = {8, 4, -9, -2};    Plane Surface(2) = {2};
Curve Loop(3) = {10, 5, -11, -3};  Plane Surface(3) = {3};
Curve Loop(4) = {11, 6, -12, -4};  Plane Surface(4) = {4};

Transfinite Curve{1, 2, 3, 4, 5, 6} = n_around + 1;
Transfinite Curve{7, 8, 9} = 2;
Transfinite Curve{10, 11, 12} = n_radial + 1 Using Progression growth;
Transfinite Surface{1, 2, 3, 4};
Recombine Surface{1, 2, 3, 4};

Physical Surface("soil", 1) = {3, 4};
If (zero_thickness)
  Physical Surface("pile skin", 2) = {1, 2};
  Physical Curve("contact", 4) = {3, 4};
Else
  Physical Surface("contact layer", 2) = {1, 2};
EndIf
Physical Curve("pile", 1) = {1, 2};
Physical Curve("axis of symmetry", 2) = {7, 9, 10, 12};
Physical Curve("outer", 3) = {5, 6};
