// Griffiths (Figure 2): a unit-width column crossed by an inclined band of
// elements (the interface), one element thick, between two blocks.
//
// Parameters (set from the parameter file's "Mesh/Geometry parameters"):
//   alpha             inclination of the interface to the horizontal (deg)
//   aspect_ratio      interface length / thickness, l/t with l = 1/cos(alpha)
//   block_height      height of each block at its shortest side
//   elements_along    elements along the interface (and across the column)
//   elements_block    elements up each block
//   x0                x of the column's left side (default 0; off the axis
//                     when the column is revolved as a hollow cylinder)
//   zero_thickness    1: no band; the blocks meet on the inclined line,
//                     physical curve 3, for zero-thickness interface
//                     elements ("Interface 3")
//
// Physical groups:
//   surface 1 "block"      the column above and below the interface
//   surface 2 "interface"  the inclined band (none with zero_thickness)
//   curve   3 "interface"  the inclined line (zero_thickness only)
//   curve   1 "bottom"     base of the column (y = 0)
//   curve   2 "top"        top of the column
DefineConstant[
  alpha          = {45, Name "Parameters/alpha"},
  aspect_ratio   = {10, Name "Parameters/aspect_ratio"},
  block_height   = {1, Name "Parameters/block_height"},
  elements_along = {8, Name "Parameters/elements_along"},
  elements_block = {8, Name "Parameters/elements_block"},
  x0             = {0, Name "Parameters/x0"},
  zero_thickness = {0, Name "Parameters/zero_thickness"}
];

a  = alpha * Pi / 180;
l  = 1 / Cos(a);              // interface length across the unit width
t  = zero_thickness ? 0 : l / aspect_ratio;   // band thickness, normal to it
tv = t / Cos(a);              // its vertical extent
rise = Tan(a);                // vertical rise of the band across the column
H  = 2 * block_height + tv + rise;

Point(1) = {x0 + 0, 0, 0};
Point(2) = {x0 + 1, 0, 0};
Point(3) = {x0 + 1, block_height + rise, 0};
Point(4) = {x0 + 0, block_height, 0};
If (zero_thickness)
  // The upper block starts on the lower block's top line.
  Point(7) = {x0 + 0, H, 0};
  Point(8) = {x0 + 1, H, 0};
  Line(1)  = {1, 2};   // bottom
  Line(2)  = {2, 3};
  Line(3)  = {4, 3};   // the interface
  Line(4)  = {1, 4};
  Line(8)  = {3, 8};
  Line(9)  = {7, 8};   // top
  Line(10) = {4, 7};
  Curve Loop(1) = {1, 2, -3, -4};  Plane Surface(1) = {1};
  Curve Loop(3) = {3, 8, -9, -10}; Plane Surface(3) = {3};
  Transfinite Curve{1, 3, 9} = elements_along + 1;
  Transfinite Curve{2, 4, 8, 10} = elements_block + 1;
  Transfinite Surface{1, 3};
  Recombine Surface{1, 3};
  Physical Surface("block", 1) = {1, 3};
  Physical Curve("bottom", 1) = {1};
  Physical Curve("top", 2) = {9};
  Physical Curve("interface", 3) = {3};
Else
  Point(5) = {x0 + 0, block_height + tv, 0};
  Point(6) = {x0 + 1, block_height + tv + rise, 0};
  Point(7) = {x0 + 0, H, 0};
  Point(8) = {x0 + 1, H, 0};

  Line(1)  = {1, 2};   // bottom
  Line(2)  = {2, 3};
  Line(3)  = {4, 3};   // lower face of the interface
  Line(4)  = {1, 4};
  Line(5)  = {3, 6};
  Line(6)  = {5, 6};   // upper face of the interface
  Line(7)  = {4, 5};
  Line(8)  = {6, 8};
  Line(9)  = {7, 8};   // top
  Line(10) = {5, 7};

  Curve Loop(1) = {1, 2, -3, -4};   Plane Surface(1) = {1};   // lower block
  Curve Loop(2) = {3, 5, -6, -7};   Plane Surface(2) = {2};   // interface
  Curve Loop(3) = {6, 8, -9, -10};  Plane Surface(3) = {3};   // upper block

  Transfinite Curve{1, 3, 6, 9} = elements_along + 1;
  Transfinite Curve{2, 4, 8, 10} = elements_block + 1;
  Transfinite Curve{5, 7} = 2;
  Transfinite Surface{1, 2, 3};
  Recombine Surface{1, 2, 3};

  Physical Surface("block", 1) = {1, 3};
  Physical Surface("interface", 2) = {2};
  Physical Curve("bottom", 1) = {1};
  Physical Curve("top", 2) = {9};
EndIf
