// The block on its base of meshes/tet_block_on_base.geo with element sizes
// 0.6 (base) and 0.45 (block): on 2 ranks, cells of one rank touch the
// base bottom (id 2) at an edge or a vertex only, beside a face of the
// other rank (the test scenes/forces_two_ranks_01, outside-user audit,
// round 7). Boundary ids: 1 block top, 2 base bottom, 3 block bottom,
// 4 base top.
//   gmsh -3 tet_block_forces.geo -o tet_block_forces.msh
SetFactory("OpenCASCADE");
Mesh.MshFileVersion = 2.2;
Box(1) = {-1, -1, 0, 2, 2, 0.4};
Box(2) = {-0.5, -0.5, 0.4, 1, 1, 0.5};
e = 1e-6;
Physical Volume(1) = {2};
Physical Volume(2) = {1};
Physical Surface(1) = {Surface In BoundingBox{-0.5-e, -0.5-e, 0.9-e, 0.5+e, 0.5+e, 0.9+e}};
Physical Surface(2) = {Surface In BoundingBox{-1-e, -1-e, -e, 1+e, 1+e, e}};
// The block's bottom lies inside the base's top's box: take it out.
s3[] = Surface In BoundingBox{-0.5-e, -0.5-e, 0.4-e, 0.5+e, 0.5+e, 0.4+e};
s4[] = Surface In BoundingBox{-1-e, -1-e, 0.4-e, 1+e, 1+e, 0.4+e};
s4[] -= s3[];
Physical Surface(3) = {s3[]};
Physical Surface(4) = {s4[]};
MeshSize{PointsOf{Volume{1};}} = 0.6;
MeshSize{PointsOf{Volume{2};}} = 0.45;
