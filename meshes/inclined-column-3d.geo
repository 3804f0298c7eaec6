// Griffiths' column (inclined-column.geo) extruded along z: a column of
// unit width and depth `depth`, crossed by an inclined slab of hexahedra
// one element thick (the interface).
//
// Parameters: those of inclined-column.geo (alpha, aspect_ratio,
// block_height, elements_along, elements_block, x0, zero_thickness), and
//   depth            the column's extent along z
//   elements_depth   elements along z
//
// Physical groups:
//   volume  1 "block"      the column above and below the interface
//   volume  2 "interface"  the inclined slab (none with zero_thickness)
//   surface 3 "interface"  the inclined plane where the blocks meet
//                          (zero_thickness only), for zero-thickness
//                          interface elements ("Interface 3")
//   surface 1 "bottom"     base of the column (y = 0)
//   surface 2 "top"        top of the column
//   surface 5 "back"       the face z = 0
//   surface 6 "front"      the face z = depth
DefineConstant[
  depth          = {0.25, Name "Parameters/depth"},
  elements_depth = {1, Name "Parameters/elements_depth"}
];

Include "inclined-column.geo";
Delete Physicals;

If (zero_thickness)
  // For each of the surfaces 1 (lower block) and 3 (upper block) six
  // entries: the far face, the volume, and the faces swept by the curves of
  // its loop in order (1: 1, 2, 3, 4; 3: 3, 8, 9, 10).
  out[] = Extrude {0, 0, depth} {
    Surface{1, 3}; Layers{elements_depth}; Recombine;
  };
  Physical Volume("block", 1) = {out[1], out[7]};
  Physical Surface("bottom", 1) = {out[2]};
  Physical Surface("top", 2) = {out[10]};
  Physical Surface("interface", 3) = {out[4]};
  Physical Surface("back", 5) = {1, 3};
  Physical Surface("front", 6) = {out[0], out[6]};
Else
  // For each of the surfaces 1 (lower block), 2 (interface) and 3 (upper
  // block) six entries: the far face, the volume, and the faces swept by
  // the curves of its loop in order (1: 1, 2, 3, 4; 3: 6, 8, 9, 10).
  out[] = Extrude {0, 0, depth} {
    Surface{1, 2, 3}; Layers{elements_depth}; Recombine;
  };
  Physical Volume("block", 1) = {out[1], out[13]};
  Physical Volume("interface", 2) = {out[7]};
  Physical Surface("bottom", 1) = {out[2]};
  Physical Surface("top", 2) = {out[16]};
  Physical Surface("back", 5) = {1, 2, 3};
  Physical Surface("front", 6) = {out[0], out[6], out[12]};
EndIf
