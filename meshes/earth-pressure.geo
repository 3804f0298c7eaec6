// Griffiths' Case 4 (Figure 11): passive earth pressure. Soil to the right
// of a wall of height H on x = 0; there is no wall element: the wall acts
// through prescribed displacements of the soil's nodes on it. A thin column
// of elements runs down the wall: the interface (its own material) over
// the wall's height, ordinary soil below the wall's toe.
//
// Parameters:
//   wall_height    H
//   width          width of the soil
//   depth          depth of the soil (> H)
//   aspect_ratio   H / t, with t the width of the column
//   n_wall         elements down the wall
//   n_below        elements from the wall's toe to the bottom
//   n_x            elements from the column to the side
//   growth         ratio of neighbouring element sizes away from the wall
//   refinement     multiplies every element count (and refines the grading)
//   zero_thickness 1: the column over the wall's height is the wall itself
//                  (a body of width t, material 2), joined to the soil by
//                  zero-thickness interface elements on its face (curve 6)
//                  and its toe (curve 7)
//
// Physical groups:
//   surfaces 1 "soil", 2 "wall column" (the interface)
//   curves   1 "wall" (x = 0, -H < y < 0), 2 "below wall" (x = 0, y < -H),
//            3 "bottom", 4 "side" (x = width), 5 "ground" (y = 0);
//            zero_thickness: 6 "wall face" (x = t), 7 "wall toe" (y = -H)
DefineConstant[
  wall_height  = {1, Name "Parameters/wall_height"},
  width        = {3, Name "Parameters/width"},
  depth        = {2, Name "Parameters/depth"},
  aspect_ratio = {10, Name "Parameters/aspect_ratio"},
  n_wall       = {10, Name "Parameters/n_wall"},
  n_below      = {5, Name "Parameters/n_below"},
  n_x          = {12, Name "Parameters/n_x"},
  growth       = {1.15, Name "Parameters/growth"},
  refinement   = {1, Name "Parameters/refinement"},
  zero_thickness = {0, Name "Parameters/zero_thickness"}
];

H = wall_height;
t = H / aspect_ratio;

Point(1) = {0, 0, 0};
Point(2) = {t, 0, 0};
Point(3) = {width, 0, 0};
Point(4) = {0, -H, 0};
Point(5) = {t, -H, 0};
Point(6) = {width, -H, 0};
Point(7) = {0, -depth, 0};
Point(8) = {t, -depth, 0};
Point(9) = {width, -depth, 0};

// Horizontal lines, away from the wall.
Line(1) = {1, 2};  Line(2) = {2, 3};      // ground
Line(3) = {4, 5};  Line(4) = {5, 6};      // level of the toe
Line(5) = {7, 8};  Line(6) = {8, 9};      // bottom
// Vertical lines, downwards.
Line(7)  = {1, 4}; Line(8)  = {2, 5}; Line(9)  = {3, 6};   // wall height
Line(10) = {4, 7}; Line(11) = {5, 8}; Line(12) = {6, 9};   // below

Curve Loop(1) = {1, 8, -3, -7};   Plane Surface(1) = {1};  // wall column
Curve Loop(2) = {2, 9, -4, -8};   Plane Surface(2) = {2};  // soil beside it
Curve Loop(3) = {3, 11, -5, -10}; Plane Surface(3) = {3};  // column below the toe
Curve Loop(4) = {4, 12, -6, -11}; Plane Surface(4) = {4};  // soil below

r = growth^(1 / refinement);
Transfinite Curve{1, 3, 5} = 2;                            // one element wide
Transfinite Curve{2, 4, 6} = refinement * n_x + 1 Using Progression r;
Transfinite Curve{7, 8, 9} = refinement * n_wall + 1;
Transfinite Curve{10, 11, 12} = refinement * n_below + 1 Using Progression r;
Transfinite Surface{1, 2, 3, 4};
Recombine Surface{1, 2, 3, 4};

Physical Surface("soil", 1) = {2, 3, 4};
If (zero_thickness)
  Physical Surface("wall", 2) = {1};
  Physical Curve("wall face", 6) = {8};
  Physical Curve("wall toe", 7) = {3};
Else
  Physical Surface("wall column", 2) = {1};
EndIf
Physical Curve("wall", 1) = {7};
Physical Curve("below wall", 2) = {10};
Physical Curve("bottom", 3) = {5, 6};
Physical Curve("side", 4) = {12, 9};
Physical Curve("ground", 5) = {1, 2};
