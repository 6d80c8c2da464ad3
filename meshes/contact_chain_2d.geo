// contact_chain_2d.geo - a chain of contact pairs (issue 32 item 1, the
// closure of the constraint lines): a base L (0..2 x 0..0.5, 4 x 1 cells),
// a block M on its left half (0..1 x 0.5..1, 2 x 2 cells) and a block R
// beside M (1..2 x 0.55..1.05, 1 x 8 cells), clear of the base by 0.05.
// M's bottom is a slave on L's top, R's left side a slave on M's right
// side: M's corner node (1, 0.5) is a slave of the first pair and a master
// of the second, so a line of R chains through M's line to L.
// Boundary ids: 1 L's bottom, 2 L's top, 3 M's bottom, 4 M's right side,
// 5 R's left side, 6 M's top, 7 R's right side, 8 M's left side, 9 R's
// top, 10 R's bottom. Material ids 1 (L), 2 (M), 3 (R).
//   gmsh -2 meshes/contact_chain_2d.geo -o meshes/contact_chain_2d.msh
Geometry.AutoCoherence = 0;   // each body keeps its own nodes
Mesh.MshFileVersion    = 2.2;
x0[] = {0, 0, 1};
x1[] = {2, 1, 2};
y0[] = {0, 0.5, 0.55};
y1[] = {0.5, 1, 1.05};
nx[] = {4, 2, 1};
ny[] = {1, 2, 8};
For body In {0:2}
  o = 10 * body;
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
  Physical Surface(1 + body) = {o + 1};
EndFor
Physical Curve(1) = {1};
Physical Curve(2) = {3};
Physical Curve(3) = {11};
Physical Curve(4) = {12};
Physical Curve(5) = {24};
Physical Curve(6) = {13};
Physical Curve(7) = {22};
Physical Curve(8) = {14};
Physical Curve(9) = {23};
Physical Curve(10) = {21};
