// A block on a long strip for 3D large sliding (tests/scenes/
// current_kinematics_sliding_far_3d_01): the block (material 1) 1 x 1 x 0.5
// over [-0.5, 0.5]^2, on the strip (material 2) 2.7 x 1.8 x 0.25 over
// [-0.75, 1.95] x [-0.79, 1.01], each meshed on its own (the bodies share no
// node). The strip's top has nx x ny faces (default 27 x 4: 0.1 along x,
// 0.45 along y), the block's base nb x nb (default 3): a slave node slid by
// 1.2 along x passes over 13 strip faces. The strip's grid lines miss
// the block's edges, before and after a slide of (1.2, 0.3), by at least
// 0.015 (no coincident edges in the segmentation). Hexahedra: each plan is
// extruded. Boundary ids: 1 block top, 2 strip bottom, 3 block bottom,
// 4 strip top.
//   gmsh -3 sliding_strip_3d.geo -o sliding_strip_3d.msh
// (MSH 2.2, ASCII.)
SetFactory("OpenCASCADE");
If (!Exists(nb)) nb = 3; EndIf
If (!Exists(nx)) nx = 27; EndIf
If (!Exists(ny)) ny = 4; EndIf
If (!Exists(nz)) nz = 2; EndIf
Mesh.MshFileVersion = 2.2;
e = 1e-6;

Rectangle(1) = {-0.75, -0.79, 0, 2.7, 1.8};
strip[] = Extrude {0, 0, 0.25} { Surface{1}; Layers{1}; Recombine; };
s2 = news;
Rectangle(s2) = {-0.5, -0.5, 0.25, 1, 1};
block[] = Extrude {0, 0, 0.5} { Surface{s2}; Layers{nz}; Recombine; };

// The strip's edges along x (at y = -0.79 and 1.01) and along y.
Transfinite Curve{Curve In BoundingBox{-0.75 - e, -0.79 - e, -e, 1.95 + e, -0.79 + e, e},
                  Curve In BoundingBox{-0.75 - e, 1.01 - e, -e, 1.95 + e, 1.01 + e, e}} = nx + 1;
Transfinite Curve{Curve In BoundingBox{-0.75 - e, -0.79 - e, -e, -0.75 + e, 1.01 + e, e},
                  Curve In BoundingBox{1.95 - e, -0.79 - e, -e, 1.95 + e, 1.01 + e, e}} = ny + 1;
Transfinite Surface{1};
Transfinite Curve{Curve In BoundingBox{-0.5 - e, -0.5 - e, 0.25 - e, 0.5 + e, 0.5 + e, 0.25 + e}} = nb + 1;
Transfinite Surface{s2};
Recombine Surface{1, s2};

Physical Volume(1) = {block[1]};
Physical Volume(2) = {strip[1]};
Physical Surface(1) = {block[0]};
Physical Surface(2) = {1};
Physical Surface(3) = {s2};
Physical Surface(4) = {strip[0]};
