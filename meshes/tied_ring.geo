// tied_ring.geo - a quarter of a thick-walled cylinder (Lame's problem),
// inner radius 1, outer 2, cut along the circle r = 1.5 (mesh tying,
// Contact/Tied pairs): the inner part (physical surface 1) with na cells
// around the quarter, the outer part (2) with nb, each 2 cells across;
// with cut = 1 each part has its own nodes on the cut (non-matching when
// na != nb), with cut = 0 they share it (the uncut ring, nb = na).
// Set with -setnumber: na, nb (default 6, 8), cut (default 1).
// Boundary ids: 1 the inner arc r = 1, 2 the outer arc r = 2, 3 the inner
// part's side of the cut, 4 the outer part's (cut = 1 only), 5 the edges
// on y = 0, 6 the edges on x = 0.
//   gmsh -2 meshes/tied_ring.geo -o out.msh
Geometry.AutoCoherence = 0;
Mesh.MshFileVersion    = 2.2;
If (!Exists(na)) na = 6; EndIf
If (!Exists(nb)) nb = 8; EndIf
If (!Exists(cut)) cut = 1; EndIf
If (cut == 0) nb = na; EndIf
Point(100) = {0, 0, 0};
Point(1) = {1, 0, 0};
Point(2) = {1.5, 0, 0};
Point(3) = {0, 1.5, 0};
Point(4) = {0, 1, 0};
Line(1) = {1, 2};
Circle(2) = {2, 100, 3};
Line(3) = {3, 4};
Circle(4) = {4, 100, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{2, 4} = na + 1;
Transfinite Curve{1, 3} = 3;
If (cut == 1)
  Point(12) = {1.5, 0, 0};
  Point(13) = {0, 1.5, 0};
  Circle(12) = {13, 100, 12};
EndIf
a = cut == 1 ? 12 : 2;
b = cut == 1 ? 13 : 3;
Point(15) = {2, 0, 0};
Point(16) = {0, 2, 0};
Line(11) = {a, 15};
Circle(13) = {15, 100, 16};
Line(14) = {16, b};
If (cut == 1)
  Curve Loop(11) = {11, 13, 14, 12};
  Transfinite Curve{12} = nb + 1;
Else
  Curve Loop(11) = {11, 13, 14, -2};
EndIf
Plane Surface(11) = {11};
Transfinite Curve{13} = nb + 1;
Transfinite Curve{11, 14} = 3;
Transfinite Surface{1};
Transfinite Surface{11};
Recombine Surface{1, 11};
Physical Surface(1) = {1};
Physical Surface(2) = {11};
Physical Curve(1) = {4};
Physical Curve(2) = {13};
If (cut == 1)
  Physical Curve(3) = {2};
  Physical Curve(4) = {12};
EndIf
Physical Curve(5) = {1, 11};
Physical Curve(6) = {3, 14};
