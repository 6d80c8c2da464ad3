// tied_cantilever.geo - a cantilever 4 x 1 cut at x = 2 (mesh tying,
// Contact/Tied pairs): the left part (physical surface 1, [0, 2] x [0, 1])
// with n1 cells across the height, the right part (2, [2, 4] x [0, 1]) with
// n2, cells about square. With cut = 1 the parts are meshed on their own
// (the cut is non-matching, each part has its own nodes on it); with
// cut = 0 they share the line x = 2 (the uncut beam, n2 = n1).
// Set with -setnumber: n1, n2 (default 3, 4), cut (default 1).
// Boundary ids: 1 the clamped end x = 0, 2 the loaded end x = 4, 3 the left
// part's side of the cut, 4 the right part's (cut = 1 only).
//   gmsh -2 -setnumber n1 3 -setnumber n2 4 meshes/tied_cantilever.geo -o out.msh
Geometry.AutoCoherence = 0;
Mesh.MshFileVersion    = 2.2;
If (!Exists(n1)) n1 = 3; EndIf
If (!Exists(n2)) n2 = 4; EndIf
If (!Exists(cut)) cut = 1; EndIf
If (cut == 0) n2 = n1; EndIf

Point(1) = {0, 0, 0};
Point(2) = {2, 0, 0};
Point(3) = {2, 1, 0};
Point(4) = {0, 1, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 3} = 2 * n1 + 1;
Transfinite Curve{2, 4} = n1 + 1;

If (cut == 1)
  Point(12) = {2, 0, 0};
  Point(13) = {2, 1, 0};
  Line(12) = {13, 12};
Else
  Point(12) = {2, 0, 0}; // unused
EndIf
a = cut == 1 ? 12 : 2;   // the right part's corners on the cut
b = cut == 1 ? 13 : 3;
Point(15) = {4, 0, 0};
Point(16) = {4, 1, 0};
Line(11) = {a, 15};
Line(13) = {15, 16};
Line(14) = {16, b};
If (cut == 1)
  Curve Loop(11) = {11, 13, 14, 12};
Else
  Curve Loop(11) = {11, 13, 14, -2};
EndIf
Plane Surface(11) = {11};
Transfinite Curve{11, 14} = 2 * n2 + 1;
Transfinite Curve{13} = n2 + 1;
If (cut == 1)
  Transfinite Curve{12} = n2 + 1;
EndIf
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
