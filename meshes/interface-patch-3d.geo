// The two blocks of interface-patch.geo extruded along z: a box of two
// blocks, one on the other, joined along a physical surface that carries
// zero-thickness interface elements (the patch test of those elements in
// 3D).
//
// Parameters: those of interface-patch.geo (length, height, nx, ny, x0),
// and
//   depth   the blocks' extent along z
//   nz      elements along z
//
// Physical groups:
//   volume   1 "blocks"
//   surfaces 1 "bottom" (y = -h), 2 "top" (y = h), 3 "interface" (y = 0),
//            4 "left" (x = x0), 5 "right" (x = x0 + L), 6 "back" (z = 0),
//            7 "front" (z = depth)
DefineConstant[
  depth = {1, Name "Parameters/depth"},
  nz    = {2, Name "Parameters/nz"}
];

Include "interface-patch.geo";
Delete Physicals;

// For each of the surfaces 1 (lower block) and 2 (upper block) six
// entries: the far face, the volume, and the faces swept by the curves of
// its loop in order (1: 1, 2, 3, 4; 2: 3, 5, 6, 7).
out[] = Extrude {0, 0, depth} { Surface{1, 2}; Layers{nz}; Recombine; };

Physical Volume("blocks", 1) = {out[1], out[7]};
Physical Surface("bottom", 1) = {out[2]};
Physical Surface("top", 2) = {out[10]};
Physical Surface("interface", 3) = {out[4]};
Physical Surface("left", 4) = {out[5], out[11]};
Physical Surface("right", 5) = {out[3], out[9]};
Physical Surface("back", 6) = {1, 2};
Physical Surface("front", 7) = {out[0], out[6]};
