// A backfill of height H behind a vertical wall on x = 0, on a base at the
// wall's toe (y = 0) or, with depth > 0, on soil that goes on below the toe
// to a base at y = -depth. There is no wall element: the wall acts through
// prescribed displacements of the nodes on x = 0. A column of elements of
// width t runs down the wall: the wall's interface (its own material) or,
// with zero_thickness = 1, the wall's skin (a body of its own material)
// joined to the backfill by zero-thickness interface elements on its face.
//
// Parameters:
//   height          H
//   width           the backfill's extent from the wall
//   layer           t, the column's width
//   n_height        elements up the wall (and the backfill)
//   n_width         elements across the backfill
//   growth          ratio of neighbouring element widths away from the wall
//   zero_thickness  1: the column is the wall's skin, and the line between
//                   it and the backfill is physical curve 6 for
//                   zero-thickness interface elements ("Interface 6")
//   depth           D >= 0, the soil's depth below the toe (0: none, the
//                   base at the toe). A passive mechanism on a rough wall
//                   dips below the toe, which a base there would cut off.
//   n_depth         elements from the toe down to the base (depth > 0)
//   depth_growth    ratio of neighbouring element heights down from the toe
//
// Physical groups (the wall's id the lowest, so that its displacement
// wins at the toe):
//   surfaces 1 "backfill", 2 "wall column"
//   curves   1 "wall" (x = 0, 0 < y < H), 2 "column toe" (y = 0,
//            0 < x < t; none with depth > 0: it lies inside the soil),
//            3 "base" (y = 0, x > t; with depth > 0 y = -D, 0 < x),
//            4 "far side" (x = t + width), 5 "ground" (y = H),
//            7 "below the wall" (x = 0, -D < y < 0; depth > 0 only);
//            zero_thickness: 6 "column face" (x = t, 0 < y < H; with
//            depth > 0 also the skin's foot, y = 0, 0 < x < t)
DefineConstant[
  height         = {1, Name "Parameters/height"},
  width          = {3, Name "Parameters/width"},
  layer          = {0.02, Name "Parameters/layer"},
  n_height       = {12, Name "Parameters/n_height"},
  n_width        = {24, Name "Parameters/n_width"},
  growth         = {1.08, Name "Parameters/growth"},
  zero_thickness = {0, Name "Parameters/zero_thickness"},
  depth          = {0, Name "Parameters/depth"},
  n_depth        = {6, Name "Parameters/n_depth"},
  depth_growth   = {1.2, Name "Parameters/depth_growth"}
];

H = height;
t = layer;

Point(1) = {0, 0, 0}; Point(2) = {t, 0, 0}; Point(3) = {t + width, 0, 0};
Point(4) = {0, H, 0}; Point(5) = {t, H, 0}; Point(6) = {t + width, H, 0};
Line(1) = {1, 2}; Line(2) = {2, 3};          // base
Line(3) = {4, 5}; Line(4) = {5, 6};          // ground
Line(5) = {1, 4}; Line(6) = {2, 5}; Line(7) = {3, 6};
Curve Loop(1) = {1, 6, -3, -5}; Plane Surface(1) = {1};   // column
Curve Loop(2) = {2, 7, -4, -6}; Plane Surface(2) = {2};   // backfill

Transfinite Curve{1, 3} = 2;                                // one element wide
Transfinite Curve{2, 4} = n_width + 1 Using Progression growth;
Transfinite Curve{5, 6, 7} = n_height + 1;
Transfinite Surface{1, 2};
Recombine Surface{1, 2};

If (depth > 0)
  // The soil below the toe, in two blocks under the column and the
  // backfill, graded from the toe downwards.
  Point(7) = {0, -depth, 0}; Point(8) = {t, -depth, 0};
  Point(9) = {t + width, -depth, 0};
  Line(8) = {7, 8}; Line(9) = {8, 9};                      // base
  Line(10) = {7, 1}; Line(11) = {8, 2}; Line(12) = {9, 3};
  Curve Loop(3) = {8, 11, -1, -10}; Plane Surface(3) = {3};
  Curve Loop(4) = {9, 12, -2, -11}; Plane Surface(4) = {4};
  Transfinite Curve{8} = 2;
  Transfinite Curve{9} = n_width + 1 Using Progression growth;
  Transfinite Curve{10, 11, 12} = n_depth + 1 Using Progression 1 / depth_growth;
  Transfinite Surface{3, 4};
  Recombine Surface{3, 4};
  Physical Surface("backfill", 1) = {2, 3, 4};
  Physical Curve("base", 3) = {8, 9};
  Physical Curve("far side", 4) = {12, 7};
  Physical Curve("below the wall", 7) = {10};
Else
  Physical Surface("backfill", 1) = {2};
  Physical Curve("column toe", 2) = {1};
  Physical Curve("base", 3) = {2};
  Physical Curve("far side", 4) = {7};
EndIf
Physical Surface("wall column", 2) = {1};
Physical Curve("wall", 1) = {5};
Physical Curve("ground", 5) = {3, 4};
// Below a skin whose foot stands on soil (depth > 0), the foot slides on
// that soil through the same interface: a foot held to it would be a rough
// foot of width t that raised the passive thrust by 2% for t = H / 50.
If (zero_thickness && depth > 0)
  Physical Curve("column face", 6) = {6, 1};
ElseIf (zero_thickness)
  Physical Curve("column face", 6) = {6};
EndIf
