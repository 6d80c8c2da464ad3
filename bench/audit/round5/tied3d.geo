// Two boxes meshed on their own with tetrahedra (non-matching at z = 0.5),
// to be tied: upper [0,1]x[0,1]x[0.5,1] (material 1, h = 0.2), lower
// [0,1]x[0,1]x[0,0.5] (material 2, h = 0.35). Boundary ids: 1 top,
// 2 bottom, 3 upper's bottom (tied slave), 4 lower's top (master),
// 5 x = 0, 6 x = 1, 7 y = 0, 8 y = 1 (both bodies).
//   gmsh -3 tied3d.geo -o tied3d.msh
SetFactory("OpenCASCADE");
Mesh.MshFileVersion = 2.2;
Box(1) = {0, 0, 0, 1, 1, 0.5};
Box(2) = {0, 0, 0.5, 1, 1, 0.5};
e = 1e-6;
Physical Volume(1) = {2};
Physical Volume(2) = {1};
Physical Surface(1) = {Surface In BoundingBox{-e, -e, 1-e, 1+e, 1+e, 1+e}};
Physical Surface(2) = {Surface In BoundingBox{-e, -e, -e, 1+e, 1+e, e}};
s[] = Surface In BoundingBox{-e, -e, 0.5-e, 1+e, 1+e, 0.5+e};
Physical Surface(3) = {s[1]};
Physical Surface(4) = {s[0]};
Physical Surface(5) = {Surface In BoundingBox{-e, -e, -e, e, 1+e, 1+e}};
Physical Surface(6) = {Surface In BoundingBox{1-e, -e, -e, 1+e, 1+e, 1+e}};
Physical Surface(7) = {Surface In BoundingBox{-e, -e, -e, 1+e, e, 1+e}};
Physical Surface(8) = {Surface In BoundingBox{-e, 1-e, -e, 1+e, 1+e, 1+e}};
MeshSize{PointsOf{Volume{1};}} = 0.35;
MeshSize{PointsOf{Volume{2};}} = 0.2;
// Different node counts on the two sides of the interface (gmsh would
// otherwise mesh the coincident surfaces alike).
Transfinite Curve{Boundary{Surface{s[0]};}} = 4;
Transfinite Curve{Boundary{Surface{s[1]};}} = 7;
