// Audit round 4: a full lower hemisphere (R = 1, centre (0, 0, 1.6)) on a
// block [-1.2, 1.2]^2 x [0, 0.6], both tetrahedra, each on its own nodes.
// Ids: volumes 1 (hemisphere), 2 (block); surfaces 1 hemisphere flat top
// (z = 1.6), 2 block base, 3 hemisphere curved surface (slave), 4 block top
// (master), 0 the block's sides.
//   gmsh -3 -format msh22 sphere_block.geo -o sphere_block.msh
SetFactory("OpenCASCADE");
Mesh.MshFileVersion = 2.2;
R = 1; zc = 1.6; t = 0.6; w = 1.2;
Sphere(1) = {0, 0, zc, R, -Pi/2, 0, 2*Pi};
Box(2) = {-w, -w, 0, 2*w, 2*w, t};
e = 1e-6;
Physical Volume(1) = {1};
Physical Volume(2) = {2};
top[] = Surface In BoundingBox{-R-e, -R-e, zc-e, R+e, R+e, zc+e};
all[] = Boundary{ Volume{1}; };
all[] -= top[];
Physical Surface(1) = {top[]};
Physical Surface(2) = {Surface In BoundingBox{-w-e, -w-e, -e, w+e, w+e, e}};
Physical Surface(3) = {all[]};
Physical Surface(4) = {Surface In BoundingBox{-w-e, -w-e, t-e, w+e, w+e, t+e}};
pole() = Point In BoundingBox{-e, -e, t-e, e, e, t+e};
Field[1] = Distance; Field[1].PointsList = {pole()};
Field[2] = Threshold; Field[2].InField = 1; Field[2].SizeMin = 0.12; Field[2].SizeMax = 0.6;
Field[2].DistMin = 0.1; Field[2].DistMax = 1.2;
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0; Mesh.MeshSizeFromPoints = 0; Mesh.MeshSizeFromCurvature = 0;
