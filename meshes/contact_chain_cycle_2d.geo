// contact_chain_cycle_2d.geo - meshes/contact_chain_2d.geo with the base's
// top split at x = 1 (a node of both parts): boundary 2 is L's top under M
// (0..1), boundary 11 L's top under R (1..2). With Pairs = 3: 2; 5: 4;
// 11: 10 the pairs form a cycle through shared nodes (M's corner, R's
// corner (1, 0.55) and L's node (1, 0.5)), which the program refuses
// (tests/failures/contact_chain_cycle_01).
// Boundary ids: 1 L's bottom, 2 L's top (0..1), 11 L's top (1..2), 3 M's
// bottom, 4 M's right side, 5 R's left side, 6 M's top, 7 R's right side,
// 8 M's left side, 9 R's top, 10 R's bottom. Material ids 1 (L), 2 (M),
// 3 (R).
//   gmsh -2 meshes/contact_chain_cycle_2d.geo -o meshes/contact_chain_cycle_2d.msh
Geometry.AutoCoherence = 0;   // each body keeps its own nodes
Mesh.MshFileVersion    = 2.2;
// L: 0..2 x 0..0.5, 4 x 1 cells, its top in two lines.
Point(1) = {0, 0, 0};
Point(2) = {2, 0, 0};
Point(3) = {2, 0.5, 0};
Point(5) = {1, 0.5, 0};
Point(4) = {0, 0.5, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 5};
Line(5) = {5, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 5, 4};
Plane Surface(1) = {1};
Transfinite Curve{1} = 5;
Transfinite Curve{3, 5} = 3;
Transfinite Curve{2, 4} = 2;
Transfinite Surface{1} = {1, 2, 3, 4};
Recombine Surface{1};
Physical Surface(1) = {1};
// M and R as in contact_chain_2d.geo.
x0[] = {0, 1};
x1[] = {1, 2};
y0[] = {0.5, 0.55};
y1[] = {1, 1.05};
nx[] = {2, 1};
ny[] = {2, 8};
For body In {0:1}
  o = 10 * (body + 1);
  Point(o + 1) = {x0[body], y0[body], 0};
  Point(o + 2) = {x1[body], y0[body], 0};
  Point(o + 3) = {x1[body], y1[body], 0};
  Point(o + 4) = {x0[body], y1[body], 0};
  Line(o + 1) = {o + 1, o + 2};  // bottom
  Line(o + 2) = {o + 2, o + 3};  // right
  Line(o + 3) = {o + 3, o + 4};  // top
  Line(o + 4) = {o + 4, o + 1};  // left
  Curve Loop(o + 1) = {o + 1, o + 2, o + 3, o + 4};
  Plane Surface(o + 1) = {o + 1};
  Transfinite Curve{o + 1, o + 3} = nx[body] + 1;
  Transfinite Curve{o + 2, o + 4} = ny[body] + 1;
  Transfinite Surface{o + 1};
  Recombine Surface{o + 1};
  Physical Surface(2 + body) = {o + 1};
EndFor
Physical Curve(1) = {1};
Physical Curve(2) = {5};
Physical Curve(11) = {3};
Physical Curve(3) = {11};
Physical Curve(4) = {12};
Physical Curve(5) = {24};
Physical Curve(6) = {13};
Physical Curve(7) = {22};
Physical Curve(8) = {14};
Physical Curve(9) = {23};
Physical Curve(10) = {21};
