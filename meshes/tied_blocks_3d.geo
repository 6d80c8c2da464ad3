// tied_blocks_3d.geo - two blocks for the 3D tied patch tests (mesh tying,
// Contact/Tied pairs): the lower one [0, 1]^2 x [0, 0.5] (material 1), the
// upper one [0, 1]^2 x [0.5, 1] (material 2), each meshed on its own
// (OpenCASCADE keeps the coincident faces at z = 0.5 apart: the bodies share
// no node), hexahedra extruded from each block's plan. The geometry of
// contact_blocks_3d.geo with every outer face tagged, so that any uniform
// stress can be applied as tractions.
// Set the cells with -setnumber:
//   nl, nu: cells along x and y of the lower and upper block (default 3, 2),
//   nz:     cells through the height of each block (default 2),
//   free:   1 = the upper block's plan unstructured (size 1 / nu).
// Boundary ids: 1 top z = 1, 2 bottom z = 0, 3 the lower block's side of the
// interface, 4 the upper block's, 5 the faces x = 0, 6 y = 0, 7 x = 1,
// 8 y = 1 (both blocks).
//   gmsh -3 -setnumber nl 3 -setnumber nu 2 tied_blocks_3d.geo -o out.msh
SetFactory("OpenCASCADE");
If (!Exists(nl)) nl = 3; EndIf
If (!Exists(nu)) nu = 2; EndIf
If (!Exists(nz)) nz = 2; EndIf
If (!Exists(free)) free = 0; EndIf
Mesh.MshFileVersion = 2.2;
e = 1e-6;

Rectangle(1) = {0, 0, 0, 1, 1};
lower[] = Extrude {0, 0, 0.5} { Surface{1}; Layers{nz}; Recombine; };
s2 = news;
Rectangle(s2) = {0, 0, 1, 1, 1};
upper[] = Extrude {0, 0, -0.5} { Surface{s2}; Layers{nz}; Recombine; };

Transfinite Curve{Curve In BoundingBox{-e, -e, -e, 1 + e, 1 + e, e}} = nl + 1;
Transfinite Surface{1};
top_curves[] = Curve In BoundingBox{-e, -e, 1 - e, 1 + e, 1 + e, 1 + e};
If (free == 0)
  Transfinite Curve{top_curves[]} = nu + 1;
  Transfinite Surface{s2};
Else
  MeshSize{PointsOf{Surface{s2};}} = 1. / nu;
  Mesh.Algorithm = 6;
EndIf
Recombine Surface{1, s2};

Physical Volume(1) = {lower[1]};
Physical Volume(2) = {upper[1]};
Physical Surface(1) = {s2};
Physical Surface(2) = {1};
Physical Surface(3) = {lower[0]};
Physical Surface(4) = {upper[0]};
Physical Surface(5) = {Surface In BoundingBox{-e, -e, -e, e, 1 + e, 1 + e}};
Physical Surface(6) = {Surface In BoundingBox{-e, -e, -e, 1 + e, e, 1 + e}};
Physical Surface(7) = {Surface In BoundingBox{1 - e, -e, -e, 1 + e, 1 + e, 1 + e}};
Physical Surface(8) = {Surface In BoundingBox{-e, 1 - e, -e, 1 + e, 1 + e, 1 + e}};
