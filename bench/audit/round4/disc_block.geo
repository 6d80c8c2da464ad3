// Audit round 4, 2D: a lower half disc (R = 1, centre (0, 1.6)) on a block
// [-1.2, 1.2] x [0, 0.6], triangles, the whole arc the slave.
// Ids: surfaces 1 disc, 2 block; curves 1 disc top, 2 block base, 3 arc, 4 block top.
SetFactory("OpenCASCADE");
Mesh.MshFileVersion = 2.2;
Disk(1) = {0, 1.6, 0, 1};
Rectangle(2) = {-1.2, 1.6, 0, 2.4, 1};
BooleanDifference(3) = {Surface{1}; Delete;}{Surface{2}; Delete;};
Rectangle(4) = {-1.2, 0, 0, 2.4, 0.6};
e = 1e-6;
Physical Surface(1) = {3};
Physical Surface(2) = {4};
Physical Curve(1) = {Curve In BoundingBox{-1-e, 1.6-e, -e, 1+e, 1.6+e, e}};
Physical Curve(2) = {Curve In BoundingBox{-1.2-e, -e, -e, 1.2+e, e, e}};
arc[] = Curve In BoundingBox{-1-e, 0.6-e, -e, 1+e, 1.6+e, e};
arc[] -= {Curve In BoundingBox{-1-e, 1.6-e, -e, 1+e, 1.6+e, e}};
Physical Curve(3) = {arc[]};
Physical Curve(4) = {Curve In BoundingBox{-1.2-e, 0.6-e, -e, 1.2+e, 0.6+e, e}};
MeshSize{PointsOf{Surface{3};}} = 0.15;
MeshSize{PointsOf{Surface{4};}} = 0.3;
