// Griffiths' Case 2 (Figures 6 and 10): half of a strip footing under a
// horizontal load. The left side is the footing's centreline; a stiff,
// strong footing of half-width L sits on a thin row of interface elements
// over the soil. The row runs across the whole mesh (Figure 6) or, with
// interface_beyond_footing = 0, ends at the footing's edge, beyond which
// the soil surface is free (Figure 10, "a better mesh for modelling pure
// sliding").
//
// Parameters:
//   half_width      L, half the footing width
//   width           width of the half mesh
//   depth           depth of the soil below the row
//   footing_height  height of the footing elements
//   aspect_ratio    L / t, with t the thickness of the row
//   n_footing       elements across the footing half (and the row below it)
//   n_side          elements from the footing edge to the side
//   n_depth         elements over the soil depth
//   growth          ratio of neighbouring element sizes away from the footing
//   refinement      multiplies every element count (and refines the grading)
//   interface_beyond_footing   1: Figure 6; 0: Figure 10
//   zero_thickness  1: no row; the footing sits on the soil, and the line
//                   between them is physical curve 5, for zero-thickness
//                   interface elements ("Interface 5")
//
// Physical groups:
//   surfaces 1 "footing", 2 "interface" (none with zero_thickness), 3 "soil"
//   curves   1 "footing top" (the load), 2 "centreline" (x = 0),
//            3 "bottom", 4 "side" (x = width),
//            5 "interface" (under the footing; zero_thickness only)
DefineConstant[
  half_width     = {1, Name "Parameters/half_width"},
  width          = {5, Name "Parameters/width"},
  depth          = {3, Name "Parameters/depth"},
  footing_height = {0.5, Name "Parameters/footing_height"},
  aspect_ratio   = {10, Name "Parameters/aspect_ratio"},
  n_footing      = {8, Name "Parameters/n_footing"},
  n_side         = {12, Name "Parameters/n_side"},
  n_depth        = {10, Name "Parameters/n_depth"},
  growth         = {1.2, Name "Parameters/growth"},
  interface_beyond_footing = {1, Name "Parameters/interface_beyond_footing"},
  refinement     = {1, Name "Parameters/refinement"},
  zero_thickness = {0, Name "Parameters/zero_thickness"}
];

If (zero_thickness)
  Point(1)  = {0, -depth, 0};
  Point(2)  = {half_width, -depth, 0};
  Point(3)  = {width, -depth, 0};
  Point(4)  = {0, 0, 0};
  Point(5)  = {half_width, 0, 0};
  Point(6)  = {width, 0, 0};
  Point(10) = {0, footing_height, 0};
  Point(11) = {half_width, footing_height, 0};
  Line(1) = {1, 2};  Line(2) = {2, 3};     // bottom
  Line(3) = {4, 5};                        // under the footing: the interface
  Line(4) = {5, 6};                        // soil surface beyond
  Line(7) = {10, 11};                      // footing top
  Line(8)  = {1, 4};  Line(9) = {2, 5};  Line(10) = {3, 6};   // soil
  Line(14) = {4, 10}; Line(15) = {5, 11};                     // footing
  Curve Loop(1) = {1, 9, -3, -8};   Plane Surface(1) = {1};
  Curve Loop(2) = {2, 10, -4, -9};  Plane Surface(2) = {2};
  Curve Loop(5) = {3, 15, -7, -14}; Plane Surface(5) = {5};
  r = growth^(1 / refinement);
  Transfinite Curve{1, 3, 7} = refinement * n_footing + 1;
  Transfinite Curve{2, 4} = refinement * n_side + 1 Using Progression r;
  Transfinite Curve{8, 9, 10} = refinement * n_depth + 1 Using Progression 1 / r;
  Transfinite Curve{14, 15} = refinement * 2 + 1;
  Transfinite Surface{1, 2, 5};
  Recombine Surface{1, 2, 5};
  Physical Surface("footing", 1) = {5};
  Physical Surface("soil", 3) = {1, 2};
  Physical Curve("footing top", 1) = {7};
  Physical Curve("centreline", 2) = {8, 14};
  Physical Curve("bottom", 3) = {1, 2};
  Physical Curve("side", 4) = {10};
  Physical Curve("interface", 5) = {3};
Else
  t = half_width / aspect_ratio;

  // Columns x = 0, L, width; levels y = -depth, 0 (soil top), t (row top),
  // t + footing_height (footing top).
  Point(1)  = {0, -depth, 0};
  Point(2)  = {half_width, -depth, 0};
  Point(3)  = {width, -depth, 0};
  Point(4)  = {0, 0, 0};
  Point(5)  = {half_width, 0, 0};
  Point(6)  = {width, 0, 0};
  Point(7)  = {0, t, 0};
  Point(8)  = {half_width, t, 0};
  Point(9)  = {width, t, 0};
  Point(10) = {0, t + footing_height, 0};
  Point(11) = {half_width, t + footing_height, 0};

  // Horizontal lines, left to right.
  Line(1) = {1, 2};  Line(2) = {2, 3};     // bottom
  Line(3) = {4, 5};  Line(4) = {5, 6};     // soil top
  Line(5) = {7, 8};  Line(6) = {8, 9};     // row top
  Line(7) = {10, 11};                      // footing top
  // Vertical lines, upwards.
  Line(8)  = {1, 4};  Line(9) = {2, 5};  Line(10) = {3, 6};   // soil
  Line(11) = {4, 7};  Line(12) = {5, 8}; Line(13) = {6, 9};   // row
  Line(14) = {7, 10}; Line(15) = {8, 11};                     // footing

  Curve Loop(1) = {1, 9, -3, -8};    Plane Surface(1) = {1};  // soil under the footing
  Curve Loop(2) = {2, 10, -4, -9};   Plane Surface(2) = {2};  // soil beyond
  Curve Loop(3) = {3, 12, -5, -11};  Plane Surface(3) = {3};  // row under the footing
  If (interface_beyond_footing)
    Curve Loop(4) = {4, 13, -6, -12};  Plane Surface(4) = {4};  // row beyond
  EndIf
  Curve Loop(5) = {5, 15, -7, -14};  Plane Surface(5) = {5};  // footing

  r = growth^(1 / refinement);
  Transfinite Curve{1, 3, 5, 7} = refinement * n_footing + 1;
  Transfinite Curve{2, 4, 6} = refinement * n_side + 1 Using Progression r;
  Transfinite Curve{8, 9, 10} = refinement * n_depth + 1 Using Progression 1 / r;
  Transfinite Curve{11, 12, 13} = 2;   // the row: one element thick
  Transfinite Curve{14, 15} = refinement * 2 + 1;
  Transfinite Surface{1, 2, 3, 5};
  Recombine Surface{1, 2, 3, 5};
  If (interface_beyond_footing)
    Transfinite Surface{4};
    Recombine Surface{4};
  EndIf

  Physical Surface("footing", 1) = {5};
  If (interface_beyond_footing)
    Physical Surface("interface", 2) = {3, 4};
    Physical Curve("side", 4) = {10, 13};
  Else
    Physical Surface("interface", 2) = {3};
    Physical Curve("side", 4) = {10};
  EndIf
  Physical Surface("soil", 3) = {1, 2};
  Physical Curve("footing top", 1) = {7};
  Physical Curve("centreline", 2) = {8, 11, 14};
  Physical Curve("bottom", 3) = {1, 2};
EndIf
