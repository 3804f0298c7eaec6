// The radial (r-z) plane of a pile's shaft in soil, for a Fourier analysis
// (x is r, y is z, the ground at z = 0). There is no pile element: the pile
// acts through prescribed displacements of the soil's nodes on its shaft
// (r = radius, -length < z < 0), as the wall does in earth-pressure.geo.
// A thin column of elements of width t runs down the shaft: the shaft's
// interface (its own material) over the pile's length, and below the toe a
// column of its own material, which a scene can give almost no stiffness so
// that the toe carries almost nothing (the line r = R below the toe is a
// boundary of its own).
//
// Parameters:
//   radius         R, the pile's radius (> 0: the mesh does not reach the
//                  axis)
//   length         L, the pile's embedded length
//   width          the soil's extent beyond the shaft (r = R + width)
//   depth          the soil's depth (> L)
//   thickness      t, the width of the column along the shaft
//   n_shaft        elements down the shaft
//   n_below        elements from the toe to the bottom
//   n_r            elements from the column outwards
//   growth         ratio of neighbouring element sizes away from the shaft
//                  and down from the toe
//   zero_thickness 1: the column is the pile's skin (a body of width t,
//                  material 2), joined to the soil by zero-thickness
//                  interface elements on its face (curve 6)
//
// Physical groups:
//   surfaces 1 "soil", 2 "shaft layer" (or "pile skin")
//   surface  3 "below toe" (the column under the toe)
//   curves   1 "shaft" (r = R, -L < z < 0), 2 "below toe" (r = R, z < -L),
//            3 "bottom", 4 "side" (r = R + width), 5 "ground" (z = 0);
//            zero_thickness: 6 "shaft face" (r = R + t, -L < z < 0)
DefineConstant[
  radius         = {0.5, Name "Parameters/radius"},
  length         = {10, Name "Parameters/length"},
  width          = {10, Name "Parameters/width"},
  depth          = {15, Name "Parameters/depth"},
  thickness      = {0.05, Name "Parameters/thickness"},
  n_shaft        = {20, Name "Parameters/n_shaft"},
  n_below        = {6, Name "Parameters/n_below"},
  n_r            = {12, Name "Parameters/n_r"},
  growth         = {1.2, Name "Parameters/growth"},
  zero_thickness = {0, Name "Parameters/zero_thickness"}
];

R = radius;
L = length;
t = thickness;

Point(1) = {R, 0, 0};
Point(2) = {R + t, 0, 0};
Point(3) = {R + width, 0, 0};
Point(4) = {R, -L, 0};
Point(5) = {R + t, -L, 0};
Point(6) = {R + width, -L, 0};
Point(7) = {R, -depth, 0};
Point(8) = {R + t, -depth, 0};
Point(9) = {R + width, -depth, 0};

// Horizontal lines, away from the shaft.
Line(1) = {1, 2};  Line(2) = {2, 3};      // ground
Line(3) = {4, 5};  Line(4) = {5, 6};      // level of the toe
Line(5) = {7, 8};  Line(6) = {8, 9};      // bottom
// Vertical lines, downwards.
Line(7)  = {1, 4}; Line(8)  = {2, 5}; Line(9)  = {3, 6};   // pile's length
Line(10) = {4, 7}; Line(11) = {5, 8}; Line(12) = {6, 9};   // below the toe

Curve Loop(1) = {1, 8, -3, -7};   Plane Surface(1) = {1};  // shaft column
Curve Loop(2) = {2, 9, -4, -8};   Plane Surface(2) = {2};  // soil beside it
Curve Loop(3) = {3, 11, -5, -10}; Plane Surface(3) = {3};  // column below
Curve Loop(4) = {4, 12, -6, -11}; Plane Surface(4) = {4};  // soil below

Transfinite Curve{1, 3, 5} = 2;                            // one element wide
Transfinite Curve{2, 4, 6} = n_r + 1 Using Progression growth;
Transfinite Curve{7, 8, 9} = n_shaft + 1;
Transfinite Curve{10, 11, 12} = n_below + 1 Using Progression growth;
Transfinite Surface{1, 2, 3, 4};
Recombine Surface{1, 2, 3, 4};

Physical Surface("soil", 1) = {2, 4};
Physical Surface("below toe", 3) = {3};
If (zero_thickness)
  Physical Surface("pile skin", 2) = {1};
  Physical Curve("shaft face", 6) = {8, 11};
Else
  Physical Surface("shaft layer", 2) = {1};
EndIf
Physical Curve("shaft", 1) = {7};
Physical Curve("below toe", 2) = {10};
Physical Curve("bottom", 3) = {5, 6};
Physical Curve("side", 4) = {9, 12};
Physical Curve("ground", 5) = {1, 2};
