// A block on a soil layer, joined to it through a thin layer of elements
// (its own material) or, with zero_thickness = 1, through zero-thickness
// interface elements on the line between them: the scene of a footing
// pressed down and then pushed sideways until it slides. The soil is
// structured in three columns (beside, under and beside the block).
//
// Parameters:
//   block_width     B, the block's width (centred on x = 0)
//   block_height    its height
//   layer           t, the thin layer's thickness (ignored with
//                   zero_thickness = 1)
//   soil_width      the soil's width (centred on x = 0)
//   soil_depth      its depth below the ground (y = 0)
//   n_block         elements across the block (and the layer)
//   n_block_height  elements up the block
//   n_side          elements across the soil beside the block, each side
//   n_depth         elements down the soil
//   zero_thickness  1: no layer; the block sits on the ground, and the
//                   line between them is physical curve 4 for
//                   zero-thickness interface elements ("Interface 4")
//
// Physical groups:
//   surfaces 1 "block", 2 "layer" (none with zero_thickness), 3 "soil"
//   curves   1 "block top", 2 "bottom", 3 "sides" (x = +-soil_width/2),
//            4 "interface" (under the block; zero_thickness only)
DefineConstant[
  block_width    = {1, Name "Parameters/block_width"},
  block_height   = {0.5, Name "Parameters/block_height"},
  layer          = {0.05, Name "Parameters/layer"},
  soil_width     = {4, Name "Parameters/soil_width"},
  soil_depth     = {2, Name "Parameters/soil_depth"},
  n_block        = {10, Name "Parameters/n_block"},
  n_block_height = {4, Name "Parameters/n_block_height"},
  n_side         = {6, Name "Parameters/n_side"},
  n_depth        = {8, Name "Parameters/n_depth"},
  zero_thickness = {0, Name "Parameters/zero_thickness"}
];

B = block_width;
W = soil_width;
D = soil_depth;
t = zero_thickness ? 0 : layer;

// The soil: three columns.
Point(1) = {-W / 2, -D, 0}; Point(2) = {-B / 2, -D, 0};
Point(3) = {B / 2, -D, 0};  Point(4) = {W / 2, -D, 0};
Point(5) = {-W / 2, 0, 0};  Point(6) = {-B / 2, 0, 0};
Point(7) = {B / 2, 0, 0};   Point(8) = {W / 2, 0, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4};     // bottom
Line(4) = {5, 6}; Line(5) = {6, 7}; Line(6) = {7, 8};     // ground
Line(7) = {1, 5}; Line(8) = {2, 6}; Line(9) = {3, 7}; Line(10) = {4, 8};
Curve Loop(1) = {1, 8, -4, -7};  Plane Surface(1) = {1};
Curve Loop(2) = {2, 9, -5, -8};  Plane Surface(2) = {2};
Curve Loop(3) = {3, 10, -6, -9}; Plane Surface(3) = {3};
soil[] = {1, 2, 3};

// The thin layer under the block, and the block.
If (zero_thickness)
  base = 5;
  left = 6;
  right = 7;
Else
  Point(9) = {-B / 2, t, 0}; Point(10) = {B / 2, t, 0};
  Line(11) = {9, 10}; Line(12) = {6, 9}; Line(13) = {7, 10};
  Curve Loop(4) = {5, 13, -11, -12}; Plane Surface(4) = {4};
  Transfinite Curve{12, 13} = 2;
  base = 11;
  left = 9;
  right = 10;
EndIf
Point(11) = {-B / 2, t + block_height, 0};
Point(12) = {B / 2, t + block_height, 0};
Line(14) = {left, 11}; Line(15) = {11, 12}; Line(16) = {right, 12};
Curve Loop(5) = {base, 16, -15, -14}; Plane Surface(5) = {5};

Transfinite Curve{1, 3, 4, 6} = n_side + 1;
Transfinite Curve{2, 5, 15} = n_block + 1;
Transfinite Curve{7, 8, 9, 10} = n_depth + 1;
Transfinite Curve{14, 16} = n_block_height + 1;
If (!zero_thickness)
  Transfinite Curve{11} = n_block + 1;
  Transfinite Surface{4};
  Recombine Surface{4};
EndIf
Transfinite Surface{1, 2, 3, 5};
Recombine Surface{1, 2, 3, 5};

Physical Surface("block", 1) = {5};
If (!zero_thickness)
  Physical Surface("layer", 2) = {4};
EndIf
Physical Surface("soil", 3) = {soil[]};
Physical Curve("block top", 1) = {15};
Physical Curve("bottom", 2) = {1, 2, 3};
Physical Curve("sides", 3) = {7, 10};
If (zero_thickness)
  Physical Curve("interface", 4) = {5};
EndIf
