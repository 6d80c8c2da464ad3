// Two blocks meshed on their own (triangles, non-matching at y = 0.5),
// to be tied: upper [0,1]x[0.5,1] (material 1, h = 0.13), lower
// [0,1]x[0,0.5] (material 2, h = 0.3). Boundary ids: 1 top, 2 bottom,
// 3 upper's bottom (tied slave), 4 lower's top (master), 5 left, 6 right.
//   gmsh -2 tied2d.geo -o tied2d.msh   (add -order 2 for 6-node triangles)
SetFactory("OpenCASCADE");
Mesh.MshFileVersion = 2.2;
Rectangle(1) = {0, 0, 0, 1, 0.5};
Rectangle(2) = {0, 0.5, 0, 1, 0.5};
e = 1e-6;
Physical Surface(1) = {2};
Physical Surface(2) = {1};
Physical Curve(1) = {Curve In BoundingBox{-e, 1-e, -e, 1+e, 1+e, e}};
Physical Curve(2) = {Curve In BoundingBox{-e, -e, -e, 1+e, e, e}};
c3[] = Curve In BoundingBox{-e, 0.5-e, -e, 1+e, 0.5+e, e};
Physical Curve(3) = {c3[1]};
Physical Curve(4) = {c3[0]};
Physical Curve(5) = {Curve In BoundingBox{-e, -e, -e, e, 1+e, e}};
Physical Curve(6) = {Curve In BoundingBox{1-e, -e, -e, 1+e, 1+e, e}};
MeshSize{PointsOf{Surface{1};}} = 0.3;
MeshSize{PointsOf{Surface{2};}} = 0.13;
// The two sides of the interface with different node counts (gmsh would
// otherwise mesh the coincident curves alike).
Transfinite Curve{c3[0]} = 4;
Transfinite Curve{c3[1]} = 8 Using Progression 1.15;
