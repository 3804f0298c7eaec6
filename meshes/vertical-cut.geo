// A vertical cut of height H in soil with weight: the retained soil to the
// left of the cut face x = behind, the ground in front of its toe at
// y = 0, and soil below to y = -depth. Structured quadrilaterals, the
// elements graded towards the toe.
//
// Parameters:
//   height          H, the cut's height
//   behind          width of the retained soil (from x = 0 to the face)
//   front           width of the ground in front of the toe
//   depth           depth of the soil below the toe
//   n_height        elements up the face
//   n_behind        elements across the retained soil
//   n_front         elements across the ground in front
//   n_depth         elements over the depth below the toe
//   growth          ratio of neighbouring element sizes away from the toe
//
// Physical groups:
//   surface 1 "soil"
//   curves  1 "bottom" (y = -depth), 2 "left" (x = 0), 3 "right"
//           (x = behind + front), 4 "top" (the retained soil's surface,
//           y = height), 5 "face" (the cut face), 6 "ground" (in front of
//           the toe, y = 0)
DefineConstant[
  height   = {1, Name "Parameters/height"},
  behind   = {3, Name "Parameters/behind"},
  front    = {2, Name "Parameters/front"},
  depth    = {2, Name "Parameters/depth"},
  n_height = {8, Name "Parameters/n_height"},
  n_behind = {12, Name "Parameters/n_behind"},
  n_front  = {8, Name "Parameters/n_front"},
  n_depth  = {8, Name "Parameters/n_depth"},
  growth   = {1.1, Name "Parameters/growth"}
];

Point(1) = {0, -depth, 0};
Point(2) = {behind, -depth, 0};
Point(3) = {behind + front, -depth, 0};
Point(4) = {0, 0, 0};
Point(5) = {behind, 0, 0};
Point(6) = {behind + front, 0, 0};
Point(7) = {0, height, 0};
Point(8) = {behind, height, 0};

// Curves from the toe's lines outwards, so that one Progression grades
// them all towards it.
Line(1) = {2, 1};  // bottom, under the retained soil
Line(2) = {2, 3};  // bottom, in front
Line(3) = {5, 4};  // toe level under the retained soil
Line(4) = {5, 6};  // the ground in front
Line(5) = {8, 7};  // the retained soil's surface
Line(6) = {4, 1};  // left, below the toe level
Line(7) = {4, 7};  // left, above it
Line(8) = {5, 2};  // below the toe
Line(9) = {5, 8};  // the cut face
Line(10) = {6, 3}; // right

Curve Loop(1) = {9, 5, -7, -3};
Plane Surface(1) = {1};
Curve Loop(2) = {-1, -8, 3, 6};
Plane Surface(2) = {2};
Curve Loop(3) = {2, -10, -4, 8};
Plane Surface(3) = {3};

Transfinite Curve{1, 3, 5} = n_behind + 1 Using Progression growth;
Transfinite Curve{2, 4} = n_front + 1 Using Progression growth;
Transfinite Curve{6, 8, 10} = n_depth + 1 Using Progression growth;
Transfinite Curve{7, 9} = n_height + 1;
Transfinite Surface{1, 2, 3};
Recombine Surface{1, 2, 3};

Physical Surface("soil", 1) = {1, 2, 3};
Physical Curve("bottom", 1) = {1, 2};
Physical Curve("left", 2) = {6, 7};
Physical Curve("right", 3) = {10};
Physical Curve("top", 4) = {5};
Physical Curve("face", 5) = {9};
Physical Curve("ground", 6) = {4};
