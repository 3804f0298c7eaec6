// Half of a flexible strip footing on a weightless soil layer (the
// footing's centreline is x = 0): the classic check of a code's collapse
// load against Prandtl's (2 + pi) c. Elements are graded towards the
// footing's edge and towards the surface.
//
// Parameters:
//   half_width   half the footing width, B/2
//   width        width of the half mesh
//   depth        depth of the soil layer
//   n_footing    elements under the footing half
//   n_side       elements from the footing edge to the side
//   n_depth      elements over the depth
//   growth       ratio of neighbouring element sizes away from the edge
//
// Physical groups:
//   surface 1 "soil"
//   curves  1 "footing" (top, under the footing), 2 "surface" (top, free),
//           3 "centreline" (x = 0), 4 "bottom", 5 "side" (x = width)
DefineConstant[
  half_width = {1, Name "Parameters/half_width"},
  width      = {5, Name "Parameters/width"},
  depth      = {3, Name "Parameters/depth"},
  n_footing  = {8, Name "Parameters/n_footing"},
  n_side     = {12, Name "Parameters/n_side"},
  n_depth    = {12, Name "Parameters/n_depth"},
  growth     = {1.15, Name "Parameters/growth"}
];

Point(1) = {0, 0, 0};
Point(2) = {half_width, 0, 0};
Point(3) = {width, 0, 0};
Point(4) = {0, -depth, 0};
Point(5) = {half_width, -depth, 0};
Point(6) = {width, -depth, 0};

Line(1) = {1, 2};   // footing
Line(2) = {2, 3};   // free surface, from the footing edge outwards
Line(3) = {1, 4};   // centreline, downwards
Line(4) = {2, 5};   // below the footing edge, downwards
Line(5) = {3, 6};   // side, downwards
Line(6) = {4, 5};   // bottom under the footing
Line(7) = {5, 6};   // bottom beside it

Curve Loop(1) = {1, 4, -6, -3};  Plane Surface(1) = {1};
Curve Loop(2) = {2, 5, -7, -4};  Plane Surface(2) = {2};

Transfinite Curve{1, 6} = n_footing + 1;
Transfinite Curve{2, 7} = n_side + 1 Using Progression growth;
Transfinite Curve{3, 4, 5} = n_depth + 1 Using Progression growth;
Transfinite Surface{1, 2};
Recombine Surface{1, 2};

Physical Surface("soil", 1) = {1, 2};
Physical Curve("footing", 1) = {1};
Physical Curve("surface", 2) = {2};
Physical Curve("centreline", 3) = {3};
Physical Curve("bottom", 4) = {6, 7};
Physical Curve("side", 5) = {5};
