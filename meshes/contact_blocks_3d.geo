// Two stacked blocks for the 3D contact patch test: the lower one 1 x 1 x 0.5
// (material 1), the upper one 1 x 1 x 0.5 on top of it (material 2), each
// meshed on its own (OpenCASCADE keeps the coincident faces at z = 0.5 apart:
// the bodies share no node). Hexahedra: each block's plan is extruded.
// Set the cells with -setnumber:
//   nl, nu: cells along x and y of the lower and upper block (default 3, 2),
//   nz:     cells through the height of each block (default 2),
//   free:   1 = the upper block's plan is an unstructured quadrilateral
//           mesh of size 1 / nu (cells at arbitrary angles to the lower
//           ones, some far from square) instead of nu x nu squares,
//   gap:    the upper block lifted by this much (default 0; negative: it
//           overlaps the lower one, an initial penetration),
//   dx:     the upper block shifted along x by this much (default 0: its
//           edges over the lower block's; the stability suite's grazing
//           cases put the master's edge just off the slave's).
// Boundary ids: 1 upper top, 2 lower bottom, 3 lower top, 4 upper bottom,
// 5 the faces x = 0 of both blocks, 6 the faces y = 0 of both blocks; the
// outer sides x = 1 and y = 1 are untagged (id 0).
//   gmsh -3 -setnumber nl 3 -setnumber nu 2 contact_blocks_3d.geo -o out.msh
// (MSH 2.2, ASCII; contact_fem reads MSH 1, 2 and 4.)
SetFactory("OpenCASCADE");
If (!Exists(nl)) nl = 3; EndIf
If (!Exists(nu)) nu = 2; EndIf
If (!Exists(nz)) nz = 2; EndIf
If (!Exists(free)) free = 0; EndIf
If (!Exists(gap)) gap = 0; EndIf
If (!Exists(dx)) dx = 0; EndIf
Mesh.MshFileVersion = 2.2;
e = 1e-6;

// Each block is the extrusion of one of its faces: the lower one up from
// z = 0, the upper one down from z = 1 + gap, so that the faces the mesh settings
// go to are the only ones at their height (OpenCASCADE renumbers entities
// as it goes, so they are selected by position once the geometry is done).
Rectangle(1) = {0, 0, 0, 1, 1};
lower[] = Extrude {0, 0, 0.5} { Surface{1}; Layers{nz}; Recombine; };
s2 = news;
Rectangle(s2) = {dx, 0, 1 + gap, 1, 1};
upper[] = Extrude {0, 0, -0.5} { Surface{s2}; Layers{nz}; Recombine; };

Transfinite Curve{Curve In BoundingBox{-e, -e, -e, 1 + e, 1 + e, e}} = nl + 1;
Transfinite Surface{1};
top_curves[] = Curve In BoundingBox{dx - e, -e, 1 + gap - e, 1 + dx + e, 1 + e, 1 + gap + e};
If (free == 0)
  Transfinite Curve{top_curves[]} = nu + 1;
  Transfinite Surface{s2};
Else
  // Frontal-Delaunay, recombined (the Frontal-Delaunay for quads of
  // Debian's gmsh 4.11 crashes here).
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
If (dx == 0 && gap == 0)
  Physical Surface(5) = {Surface In BoundingBox{-e, -e, -e, e, 1 + e, 1 + e}};
Else
  // The upper block's face x = dx goes with the symmetry plane x = 0.
  Physical Surface(5) = {Surface In BoundingBox{-e, -e, -e, e, 1 + e, 0.5 + e},
                         Surface In BoundingBox{dx - e, -e, 0.5 + gap - e, dx + e, 1 + e,
                                                1 + gap + e}};
EndIf
Physical Surface(6) = {Surface In BoundingBox{-Fabs(dx) - e, -e, -e, 1 + Fabs(dx) + e, e,
                                              1 + Fabs(gap) + e}};
