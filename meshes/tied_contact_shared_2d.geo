// tied_contact_shared_2d.geo - a tied surface and a contact surface that
// share a node (refused: tests/failures/tied_contact_shared_node_01): a
// lower block [0, 2] x [0, 0.5] (physical surface 1, 4 x 2 cells) and an
// upper block [0, 2] x [0.5, 1] (2, 6 x 3 cells), meshed on their own. The
// bottom of the upper block is split at x = 1 into a part to be tied
// (x < 1) and a part to be in contact (x > 1), which share the node at
// (1, 0.5); the lower block's top is split likewise.
// Boundary ids: 1 top, 2 bottom, 3 the lower top x < 1, 4 the upper bottom
// x < 1, 5 the lower top x > 1, 6 the upper bottom x > 1, 7 the sides.
//   gmsh -2 meshes/tied_contact_shared_2d.geo -o meshes/tied_contact_shared_2d.msh
Geometry.AutoCoherence = 0;   // each block keeps its own nodes
Mesh.MshFileVersion    = 2.2;
For body In {0:1}
  o = 20 * body;
  y = 0.5 * body;
  n = body == 0 ? 2 : 3;
  Point(o + 1) = {0, y, 0};
  Point(o + 2) = {1, y, 0};
  Point(o + 3) = {2, y, 0};
  Point(o + 4) = {2, y + 0.5, 0};
  Point(o + 5) = {1, y + 0.5, 0};
  Point(o + 6) = {0, y + 0.5, 0};
  Line(o + 1) = {o + 1, o + 2};  // bottom, left
  Line(o + 2) = {o + 2, o + 3};  // bottom, right
  Line(o + 3) = {o + 3, o + 4};  // right side
  Line(o + 4) = {o + 4, o + 5};  // top, right
  Line(o + 5) = {o + 5, o + 6};  // top, left
  Line(o + 6) = {o + 6, o + 1};  // left side
  Line(o + 7) = {o + 2, o + 5};  // middle
  Curve Loop(o + 1) = {o + 1, o + 7, o + 5, o + 6};
  Curve Loop(o + 2) = {o + 2, o + 3, o + 4, -(o + 7)};
  Plane Surface(o + 1) = {o + 1};
  Plane Surface(o + 2) = {o + 2};
  Transfinite Curve{o + 1, o + 2, o + 4, o + 5} = n + 1;
  Transfinite Curve{o + 3, o + 6, o + 7} = n + 1;
  Transfinite Surface{o + 1, o + 2};
  Recombine Surface{o + 1, o + 2};
EndFor
Physical Surface(1) = {1, 2};
Physical Surface(2) = {21, 22};
Physical Curve(1) = {24, 25};
Physical Curve(2) = {1, 2};
Physical Curve(3) = {5};
Physical Curve(4) = {21};
Physical Curve(5) = {4};
Physical Curve(6) = {22};
Physical Curve(7) = {3, 6, 23, 26};
