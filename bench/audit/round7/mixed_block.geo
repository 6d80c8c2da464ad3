// Round 7: mixed element shapes in contact. An upper block (material 1,
// 1 x 1 x 0.5) extruded from a 2D mesh whose left half is quadrilaterals
// and right half triangles: hexahedra and prisms in one body (they share
// nodes: one body). The base (material 2, 2 x 2 x 0.4) is tetrahedra
// (OpenCASCADE box). Bodies on their own nodes.
// Boundary ids: 1 block top, 2 base bottom, 3 block bottom, 4 base top.
//   gmsh -3 mixed_block.geo -o mixed_block.msh
SetFactory("Built-in");
Mesh.MshFileVersion = 2.2;
// The block touches the base at z0 but shares no geometric point with it.
z0 = 0.4;
// Upper block's bottom: two squares, left recombined, right triangles.
Point(1) = {-0.5, -0.5, z0}; Point(2) = {0, -0.5, z0}; Point(3) = {0.5, -0.5, z0};
Point(4) = {0.5, 0.5, z0};  Point(5) = {0, 0.5, z0};  Point(6) = {-0.5, 0.5, z0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 5};
Line(5) = {5, 6}; Line(6) = {6, 1}; Line(7) = {2, 5};
Curve Loop(1) = {1, 7, 5, 6}; Plane Surface(1) = {1};
Curve Loop(2) = {2, 3, 4, -7}; Plane Surface(2) = {2};
Transfinite Curve{1, 5, 7, 6} = 4;
Transfinite Surface{1};
Recombine Surface{1};
MeshSize{2, 3, 4, 5} = 0.2;
up[] = Extrude {0, 0, 0.5} { Surface{1, 2}; Layers{3}; Recombine; };
// up[0] top of surface 1, up[1] volume 1; then 4 sides; up[6] top of 2, up[7] volume 2
Physical Volume(1) = {up[1], up[7]};
Physical Surface(3) = {1, 2};
Physical Surface(1) = {up[0], up[6]};
// Base: a separate box of tetrahedra.
Point(101) = {-1, -1, 0}; Point(102) = {1, -1, 0}; Point(103) = {1, 1, 0}; Point(104) = {-1, 1, 0};
Line(101) = {101, 102}; Line(102) = {102, 103}; Line(103) = {103, 104}; Line(104) = {104, 101};
Curve Loop(101) = {101, 102, 103, 104}; Plane Surface(101) = {101};
MeshSize{101, 102, 103, 104} = 0.3;
bs[] = Extrude {0, 0, z0} { Surface{101}; };
Physical Volume(2) = {bs[1]};
Physical Surface(2) = {101};
Physical Surface(4) = {bs[0]};
