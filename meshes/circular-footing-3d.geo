// A circular footing on a cylinder of soil, as a 3D body of hexahedra: a
// quarter (sector = 90, the planes x = 0 and z = 0 of symmetry) or a half
// (sector = 180, the plane z = 0) of the body that circular-footing.geo
// and prandtl.geo describe by its r-z plane. y is the axis (up), the footing
// of radius R = half_width sits on the surface y = 0, and theta = 0 is the
// x axis.
//
// The plan (the x-z plane) is an O-grid: a core rectangle around the axis,
// patches from it to the footing's edge r = R, and a ring from R to the
// side r = width. It is meshed once and extruded: down through the soil,
// and, where footing = 1, up through an interface row of thickness
// t = R / aspect_ratio over the whole surface and a footing of height
// footing_height over the disc (Griffiths' Case 3). With zero_thickness = 1
// there is no row: the footing stands on the soil, the two meeting on the
// disc, a physical surface for zero-thickness interface elements. With
// footing = 0 the soil's top over the disc is the footing's base (a rigid
// footing is a prescribed displacement there).
//
// Parameters:
//   sector          90 or 180 (degrees of the circle modelled)
//   half_width      R, the footing's radius
//   width           the radius of the soil cylinder
//   depth           the depth of the soil
//   footing_height  the footing's height (footing = 1)
//   aspect_ratio    R / t, t the interface row's thickness (footing = 1)
//   n_around        elements around each 45 degrees of the circle
//   n_footing       elements along a radius from the core to R
//   n_side          elements along a radius from R to width
//   n_depth         elements over the soil depth
//   growth          ratio of neighbouring element sizes away from the
//                   footing's edge, outwards and downwards
//   core            the core's half-size as a fraction of R
//   footing         1: footing and interface row (Case 3); 0: soil only
//   zero_thickness  1 (with footing = 1): no row; the footing on the soil,
//                   joined on the disc (physical surface 7)
//
// Physical groups:
//   volumes  1 "footing", 2 "interface" (footing = 1, zero_thickness = 0),
//            3 "soil"
//   surfaces 1 "footing top" (footing = 1) or "footing base" (footing = 0:
//            the soil's surface over the disc), 2 "surface" (the soil's
//            free surface beyond the disc, footing = 0 or zero_thickness =
//            1), 3 "bottom", 4 "side" (r = width), 5 "plane z = 0", 6
//            "plane x = 0" (sector = 90), 7 "footing base" (zero_thickness
//            = 1: the disc where footing and soil meet)
DefineConstant[
  sector         = {180, Name "Parameters/sector"},
  half_width     = {1, Name "Parameters/half_width"},
  width          = {5, Name "Parameters/width"},
  depth          = {3, Name "Parameters/depth"},
  footing_height = {0.5, Name "Parameters/footing_height"},
  aspect_ratio   = {10, Name "Parameters/aspect_ratio"},
  n_around       = {4, Name "Parameters/n_around"},
  n_footing      = {4, Name "Parameters/n_footing"},
  n_side         = {8, Name "Parameters/n_side"},
  n_depth        = {8, Name "Parameters/n_depth"},
  growth         = {1.2, Name "Parameters/growth"},
  core           = {0.5, Name "Parameters/core"},
  footing        = {1, Name "Parameters/footing"},
  zero_thickness = {0, Name "Parameters/zero_thickness"}
];
If (sector != 90 && sector != 180)
  Error("circular-footing-3d.geo: sector must be 90 or 180");
EndIf

R = half_width;
a = core * R;
c45 = Cos(Pi / 4);

// The plan at y = 0: points (x, 0, z).
Point(1)  = {0, 0, 0};              // the axis
Point(2)  = {a, 0, 0};              // core, on theta = 0
Point(3)  = {a, 0, a};              // core corner at 45 degrees
Point(4)  = {R, 0, 0};              // footing edge at 0
Point(5)  = {R * c45, 0, R * c45};  // at 45
Point(6)  = {width, 0, 0};          // side at 0
Point(7)  = {width * c45, 0, width * c45};
If (sector == 90)
  Point(8)  = {0, 0, a};            // core on theta = 90
  Point(9)  = {0, 0, R};
  Point(10) = {0, 0, width};
Else
  Point(8)  = {-a, 0, a};           // core corner at 135 degrees
  Point(9)  = {-R * c45, 0, R * c45};
  Point(10) = {-width * c45, 0, width * c45};
  Point(11) = {-a, 0, 0};           // core on theta = 180
  Point(12) = {-R, 0, 0};
  Point(13) = {-width, 0, 0};
EndIf

// Core and disc.
Line(1) = {2, 3};                   // core edge facing 0..45
Line(2) = {2, 4};                   // radial on theta = 0, core to R
Line(3) = {3, 5};                   // radial at 45
Circle(4) = {4, 1, 5};              // the footing's edge, 0..45
Line(5) = {3, 8};                   // core edge facing 45..90 (..135)
Circle(6) = {5, 1, 9};              // edge 45..90 (..135)
Line(7) = {8, 9};                   // radial at 90 (135)
// Ring.
Line(8) = {4, 6};                   // radial on theta = 0, R to width
Line(9) = {5, 7};
Circle(10) = {6, 1, 7};             // side, 0..45
Line(11) = {9, 10};
Circle(12) = {7, 1, 10};            // side, 45..90 (..135)
If (sector == 90)
  Line(13) = {1, 2};                // core on theta = 0
  Line(14) = {1, 8};                // core on theta = 90
  Curve Loop(1) = {13, 1, 5, -14};  Plane Surface(1) = {1};   // core
Else
  Line(13) = {11, 2};               // core on theta = 0 and 180
  Line(14) = {8, 11};               // core edge facing 135..180
  Line(15) = {11, 12};              // radial on theta = 180
  Circle(16) = {9, 1, 12};          // edge 135..180
  Line(17) = {12, 13};
  Circle(18) = {10, 1, 13};         // side 135..180
  Curve Loop(1) = {13, 1, 5, 14};   Plane Surface(1) = {1};   // core
  Curve Loop(7) = {-14, 7, 16, -15};  Plane Surface(7) = {7}; // disc 135..180
  Curve Loop(8) = {-16, 11, 18, -17}; Plane Surface(8) = {8}; // ring 135..180
EndIf
Curve Loop(2) = {2, 4, -3, -1};     Plane Surface(2) = {2};   // disc 0..45
Curve Loop(3) = {3, 6, -7, -5};     Plane Surface(3) = {3};   // disc 45..
// Ring patches: inner arc first, so the side is the third curve.
Curve Loop(4) = {4, 9, -10, -8};    Plane Surface(4) = {4};   // ring 0..45
Curve Loop(5) = {6, 11, -12, -9};   Plane Surface(5) = {5};   // ring 45..

wide = (sector == 180) ? 2 : 1;     // the 45..135 patches span 90 degrees
Transfinite Curve{1, 4, 10} = n_around + 1;
Transfinite Curve{5, 6, 12} = wide * n_around + 1;
Transfinite Curve{2, 3, 7} = n_footing + 1;
Transfinite Curve{8, 9, 11} = n_side + 1 Using Progression growth;
If (sector == 90)
  Transfinite Curve{13} = wide * n_around + 1;
  Transfinite Curve{14} = n_around + 1;
  disc[] = {1, 2, 3};
  ring[] = {4, 5};
Else
  Transfinite Curve{13} = 2 * n_around + 1;
  Transfinite Curve{14, 16, 18} = n_around + 1;
  Transfinite Curve{15} = n_footing + 1;
  Transfinite Curve{17} = n_side + 1 Using Progression growth;
  disc[] = {1, 2, 3, 7};
  ring[] = {4, 5, 8};
EndIf
Transfinite Surface{disc[], ring[]};
Recombine Surface{disc[], ring[]};

// The soil's layers, finest at the surface: heights of the layer tops
// below y = 0 as fractions of the depth, as gmsh's Layers take them.
layers[] = {};
heights[] = {};
total = 0;
For k In {0 : n_depth - 1}
  total += growth^k;
EndFor
sum = 0;
For k In {0 : n_depth - 1}
  sum += growth^k;
  layers[] += 1;
  heights[] += sum / total;
EndFor

plan[] = {disc[], ring[]};
// Each extrusion gives, per surface: its far face, its volume, and its
// lateral faces in the order of its loop's curves.
soil[] = Extrude {0, -depth, 0} {
  Surface{plan[]}; Layers{layers[], heights[]}; Recombine;
};
n_disc = #disc[];
n_plan = #plan[];
soil_volumes[] = {};
side[] = {};
For k In {0 : n_plan - 1}
  soil_volumes[] += soil[6 * k + 1];
  If (k >= n_disc)
    side[] += soil[6 * k + 4];
  EndIf
EndFor

If (footing && zero_thickness)
  block[] = Extrude {0, footing_height, 0} {
    Surface{disc[]}; Layers{2}; Recombine;
  };
  footing_volumes[] = {};
  footing_top[] = {};
  For k In {0 : n_disc - 1}
    footing_volumes[] += block[6 * k + 1];
    footing_top[] += block[6 * k];
  EndFor
  Physical Volume("footing", 1) = {footing_volumes[]};
  Physical Surface("footing top", 1) = {footing_top[]};
  Physical Surface("surface", 2) = {ring[]};
  Physical Surface("footing base", 7) = {disc[]};
ElseIf (footing)
  t = R / aspect_ratio;
  row[] = Extrude {0, t, 0} { Surface{plan[]}; Layers{1}; Recombine; };
  row_volumes[] = {};
  disc_tops[] = {};
  For k In {0 : n_plan - 1}
    row_volumes[] += row[6 * k + 1];
    If (k < n_disc)
      disc_tops[] += row[6 * k];
    Else
      side[] += row[6 * k + 4];
    EndIf
  EndFor
  block[] = Extrude {0, footing_height, 0} {
    Surface{disc_tops[]}; Layers{2}; Recombine;
  };
  footing_volumes[] = {};
  footing_top[] = {};
  For k In {0 : n_disc - 1}
    footing_volumes[] += block[6 * k + 1];
    footing_top[] += block[6 * k];
  EndFor
  Physical Volume("footing", 1) = {footing_volumes[]};
  Physical Volume("interface", 2) = {row_volumes[]};
  Physical Surface("footing top", 1) = {footing_top[]};
Else
  Physical Surface("footing base", 1) = {disc[]};
  Physical Surface("surface", 2) = {ring[]};
EndIf
Physical Volume("soil", 3) = {soil_volumes[]};

e = 1e-6 * width;
top = footing ? ((zero_thickness ? 0 : R / aspect_ratio) + footing_height)
              : 0;
Physical Surface("bottom", 3) =
  Surface In BoundingBox{-width - e, -depth - e, -e, width + e, -depth + e,
                         width + e};
Physical Surface("side", 4) = {side[]};
Physical Surface("plane z = 0", 5) =
  Surface In BoundingBox{-width - e, -depth - e, -e, width + e, top + e, e};
If (sector == 90)
  Physical Surface("plane x = 0", 6) =
    Surface In BoundingBox{-e, -depth - e, -e, e, top + e, width + e};
EndIf
