// A homogeneous slope of height H and gradient 1 : run (vertical :
// horizontal) on a firm base or on a foundation layer: Griffiths and
// Lane's (1999) slopes, whose depth factor D is (H + depth) / H. The crest
// lies at x = behind, the toe at x = behind + run H and y = 0; the ground
// behind the crest at y = H. Structured quadrilaterals: the soil above
// the toe's level is split by a line from (behind, 0) up to the crest's
// surface at x = behind - run H / 2, so that the wedge under the face is
// a quadrilateral of its own.
//
// Parameters:
//   height     H
//   run        horizontal run of the face per unit of height (2: a 2 : 1
//              slope, 26.57 degrees)
//   behind     distance from the left side (x = 0) to the crest; more than
//              run H / 2
//   depth      depth of a foundation layer below the toe (0: none, D = 1)
//   front      width of the ground in front of the toe (with depth > 0)
//   n_height   elements up the face
//   n_behind   elements across the soil behind the split line
//   n_slope    elements along the face's wedge
//   n_depth    elements over the foundation layer's depth
//   n_front    elements across the ground in front
//
// Physical groups:
//   surface 1 "soil"
//   curves  1 "bottom" (y = -depth), 2 "left" (x = 0), 3 "right"
//           (x = behind + run H + front, with depth > 0), 4 "top" (the
//           ground behind the crest, y = H), 5 "face", 6 "ground" (in
//           front of the toe, y = 0, with depth > 0)
DefineConstant[
  height   = {10, Name "Parameters/height"},
  run      = {2, Name "Parameters/run"},
  behind   = {20, Name "Parameters/behind"},
  depth    = {0, Name "Parameters/depth"},
  front    = {10, Name "Parameters/front"},
  n_height = {10, Name "Parameters/n_height"},
  n_behind = {8, Name "Parameters/n_behind"},
  n_slope  = {12, Name "Parameters/n_slope"},
  n_depth  = {4, Name "Parameters/n_depth"},
  n_front  = {4, Name "Parameters/n_front"}
];

If (behind <= run * height / 2)
  Error("slope.geo: behind = %g must exceed run * height / 2 = %g",
        behind, run * height / 2);
EndIf

toe = behind + run * height;
split = behind - run * height / 2;

Point(1) = {0, 0, 0};
Point(2) = {behind, 0, 0};
Point(3) = {toe, 0, 0};
Point(4) = {behind, height, 0};  // crest
Point(5) = {split, height, 0};
Point(6) = {0, height, 0};

Line(1) = {1, 2};  // toe level behind the crest
Line(2) = {2, 3};  // toe level under the face
Line(3) = {3, 4};  // face
Line(4) = {4, 5};  // top, crest to the split line
Line(5) = {5, 6};  // top, the split line to the left side
Line(6) = {1, 6};  // left side above the toe's level
Line(7) = {2, 5};  // split line

Curve Loop(1) = {1, 7, 5, -6};  Plane Surface(1) = {1};
Curve Loop(2) = {2, 3, 4, -7};  Plane Surface(2) = {2};
Transfinite Curve{1, 5} = n_behind + 1;
Transfinite Curve{2, 4} = n_slope + 1;
Transfinite Curve{3, 6, 7} = n_height + 1;
Transfinite Surface{1, 2};
Recombine Surface{1, 2};

Physical Curve("left", 2) = {6};
Physical Curve("top", 4) = {4, 5};
Physical Curve("face", 5) = {3};

If (depth > 0)
  right = toe + front;
  Point(7) = {0, -depth, 0};
  Point(8) = {behind, -depth, 0};
  Point(9) = {toe, -depth, 0};
  Point(10) = {right, -depth, 0};
  Point(11) = {right, 0, 0};
  Line(8) = {7, 8};    // bottom behind the crest
  Line(9) = {8, 9};    // bottom under the face
  Line(10) = {9, 10};  // bottom in front
  Line(11) = {7, 1};   // left side below the toe's level
  Line(12) = {8, 2};
  Line(13) = {9, 3};
  Line(14) = {10, 11}; // right side
  Line(15) = {3, 11};  // ground in front of the toe
  Curve Loop(3) = {8, 12, -1, -11};  Plane Surface(3) = {3};
  Curve Loop(4) = {9, 13, -2, -12};  Plane Surface(4) = {4};
  Curve Loop(5) = {10, 14, -15, -13}; Plane Surface(5) = {5};
  Transfinite Curve{8} = n_behind + 1;
  Transfinite Curve{9} = n_slope + 1;
  Transfinite Curve{10, 15} = n_front + 1;
  Transfinite Curve{11, 12, 13, 14} = n_depth + 1;
  Transfinite Surface{3, 4, 5};
  Recombine Surface{3, 4, 5};
  Physical Surface("soil", 1) = {1, 2, 3, 4, 5};
  Physical Curve("bottom", 1) = {8, 9, 10};
  Physical Curve("left", 2) += {11};
  Physical Curve("right", 3) = {14};
  Physical Curve("ground", 6) = {15};
Else
  Physical Surface("soil", 1) = {1, 2};
  Physical Curve("bottom", 1) = {1, 2};
EndIf
