// A slab of soil resting on a thin weak seam parallel to an inclined rigid
// base: the seam on which an infinite slope slides, of finite length with
// free ends. The base rises at `angle` degrees from the origin; along it
// lie the seam (thickness `seam`) and above it the slab (thickness
// `slab`), both of length `length`, in structured quadrilaterals.
//
// Parameters:
//   length        L, along the slope
//   slab          thickness of the slab
//   seam          thickness t of the seam
//   angle         inclination beta of the base, degrees
//   n_along       elements along the slope
//   n_slab        elements through the slab (the seam has one)
//   zero_thickness 1: the seam's layer is a base layer (an ordinary body,
//                 surface 2), and the slab rests on it through
//                 zero-thickness interface elements on curve 5
//
// Physical groups:
//   surfaces 1 "slab", 2 "seam" (zero_thickness: "base layer")
//   curves   1 "base" (under the seam), 2 "upper end", 3 "lower end",
//            4 "top" (the slab's upper surface); zero_thickness: 5 "seam"
//            (the slab's underside)
DefineConstant[
  length  = {10, Name "Parameters/length"},
  slab    = {1, Name "Parameters/slab"},
  seam    = {0.05, Name "Parameters/seam"},
  angle   = {20, Name "Parameters/angle"},
  n_along = {40, Name "Parameters/n_along"},
  n_slab  = {4, Name "Parameters/n_slab"},
  zero_thickness = {0, Name "Parameters/zero_thickness"}
];

b = angle * Pi / 180;
// A point at distance s along the slope and n normal to it.
Macro Place
  Point(k) = {s * Cos(b) - n * Sin(b), s * Sin(b) + n * Cos(b), 0};
Return

k = 1; s = 0;      n = 0;           Call Place;
k = 2; s = length; n = 0;           Call Place;
k = 3; s = length; n = seam;        Call Place;
k = 4; s = 0;      n = seam;        Call Place;
k = 5; s = length; n = seam + slab; Call Place;
k = 6; s = 0;      n = seam + slab; Call Place;

Line(1) = {1, 2};  // base
Line(2) = {2, 3};  // upper end of the seam
Line(3) = {3, 4};  // the seam's top, the slab's underside
Line(4) = {4, 1};  // lower end of the seam
Line(5) = {3, 5};  // upper end of the slab
Line(6) = {5, 6};  // top
Line(7) = {6, 4};  // lower end of the slab

Curve Loop(1) = {1, 2, 3, 4};  Plane Surface(1) = {1};  // seam
Curve Loop(2) = {-3, 5, 6, 7}; Plane Surface(2) = {2};  // slab
Transfinite Curve{1, 3, 6} = n_along + 1;
Transfinite Curve{2, 4} = 2;
Transfinite Curve{5, 7} = n_slab + 1;
Transfinite Surface{1, 2};
Recombine Surface{1, 2};

Physical Surface("slab", 1) = {2};
If (zero_thickness)
  Physical Surface("base layer", 2) = {1};
  Physical Curve("seam", 5) = {3};
Else
  Physical Surface("seam", 2) = {1};
EndIf
Physical Curve("base", 1) = {1};
Physical Curve("upper end", 2) = {2, 5};
Physical Curve("lower end", 3) = {4, 7};
Physical Curve("top", 4) = {6};
