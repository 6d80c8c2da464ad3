// hertz_3d_tetrahedra.geo - the 3D Hertz scene of prm/hertz_3d.prm (quarter
// hemisphere R = 6.1237 on a quarter plate [0, 4] x [0, 4] x [0, 1], pole on
// the plate at (0, 0, 1)) meshed with tetrahedra, as a user's CAD model
// would be; contact_fem splits each tetrahedron into 4 hexahedra on reading.
//   hemisphere (physical volume 1): flat face z = 1 + R (surface 1, loaded),
//     curved surface (surface 3, slave);
//   plate (physical volume 2): base z = 0 (surface 2), top z = 1 (surface 4,
//     master), sides x = 4 and y = 4 untagged (0);
//   symmetry planes x = 0 (surface 5) and y = 0 (surface 6) of both bodies.
// The tetrahedra are 0.35 long at the pole (a = 1.35), growing to 2.5 at
// 6 from it: 355 tetrahedra, 1420 hexahedra after the split.
// The bodies are separate volumes (no BooleanFragments): they keep their
// own nodes at the pole, as contact pairs need.
// Generate: gmsh -3 -format msh22 meshes/hertz_3d_tetrahedra.geo -o meshes/hertz_3d_tetrahedra.msh
SetFactory("OpenCASCADE");
Mesh.MshFileVersion = 2.2;

R = 6.1237;
t = 1;        // plate thickness
w = 4;        // plate width
h_min = 0.35; // tetrahedron size at the pole
h_max = 2.5;  // far from it
d_max = 6;    // distance from the pole where h_max is reached
Sphere(1) = {0, 0, t + R, R, -Pi / 2, 0, Pi / 2};  // lower half, quarter in azimuth
Box(2)    = {0, 0, 0, w, w, t};

e = 1e-6;
Physical Volume(1) = {1};
Physical Volume(2) = {2};
Physical Surface(1) = Surface In BoundingBox{-e, -e, t + R - e, R + e, R + e, t + R + e};
Physical Surface(2) = Surface In BoundingBox{-e, -e, -e, w + e, w + e, e};
sphere_faces() = Boundary{ Volume{1}; };
flat_faces() = Surface In BoundingBox{-e, -e, -e, e, R + e, t + R + e};
flat_faces() += Surface In BoundingBox{-e, -e, -e, R + e, e, t + R + e};
flat_faces() += Surface In BoundingBox{-e, -e, t + R - e, R + e, R + e, t + R + e};
Physical Surface(3) = {sphere_faces()};
Physical Surface(3) -= {flat_faces()};
Physical Surface(4) = Surface In BoundingBox{-e, -e, t - e, w + e, w + e, t + e};
Physical Surface(5) = Surface In BoundingBox{-e, -e, -e, e, R + e, t + R + e};
Physical Surface(6) = Surface In BoundingBox{-e, -e, -e, R + e, e, t + R + e};

// Fine near the point of contact, coarse away from it.
pole() = Point In BoundingBox{-e, -e, t - e, e, e, t + e};
Field[1] = Distance;
Field[1].PointsList = {pole()};
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = h_min;
Field[2].SizeMax = h_max;
Field[2].DistMin = 0;
Field[2].DistMax = d_max;
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
