// Griffiths' Case 3 (Figures 8 and 10): the radial (r-z) plane of a
// circular footing of radius R on a thin interface row over soil, for a
// Fourier analysis (thinlayer's Kinematics/Type = fourier). Its geometry is
// that of the strip footing's half section, with the centreline x = 0 now
// the axis r = 0 and half_width the radius R, so it is included rather than
// repeated; every parameter of strip-footing.geo applies.
//
// Physical groups (as in strip-footing.geo):
//   surfaces 1 "footing", 2 "interface", 3 "soil"
//   curves   1 "footing top" (the load), 2 "centreline" (the axis r = 0),
//            3 "bottom", 4 "side" (r = width)
Include "strip-footing.geo";
