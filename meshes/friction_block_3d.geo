// A block on a wider base for 3D friction at large deformation: the block
// (material 1) 1 x 1 x 0.5, centred at the origin, on the base (material 2)
// 3.2 x 3.2 x 0.25 below it, each meshed on its own (the bodies share no
// node; non-matching interface: nb x nb cells on the block's base, nm x nm
// on the base's top). Hexahedra: each block's plan is extruded.
// Boundary ids: 1 block top, 2 base bottom, 3 block bottom, 4 base top.
//   gmsh -3 friction_block_3d.geo -o friction_block_3d.msh
// (MSH 2.2, ASCII.)
SetFactory("OpenCASCADE");
If (!Exists(nb)) nb = 3; EndIf
If (!Exists(nm)) nm = 8; EndIf
If (!Exists(nz)) nz = 2; EndIf
Mesh.MshFileVersion = 2.2;
e = 1e-6;

Rectangle(1) = {-1.6, -1.6, 0, 3.2, 3.2};
base[] = Extrude {0, 0, 0.25} { Surface{1}; Layers{1}; Recombine; };
s2 = news;
Rectangle(s2) = {-0.5, -0.5, 0.25, 1, 1};
block[] = Extrude {0, 0, 0.5} { Surface{s2}; Layers{nz}; Recombine; };

Transfinite Curve{Curve In BoundingBox{-1.6 - e, -1.6 - e, -e, 1.6 + e, 1.6 + e, e}} = nm + 1;
Transfinite Surface{1};
Transfinite Curve{Curve In BoundingBox{-0.5 - e, -0.5 - e, 0.25 - e, 0.5 + e, 0.5 + e, 0.25 + e}} = nb + 1;
Transfinite Surface{s2};
Recombine Surface{1, s2};

Physical Volume(1) = {block[1]};
Physical Volume(2) = {base[1]};
Physical Surface(1) = {block[0]};
Physical Surface(2) = {1};
Physical Surface(3) = {s2};
Physical Surface(4) = {base[0]};
