// tied_contact_shared_master_2d.geo - a tied and a contact pair that share
// a master node: a base block [0, 1] x [0, 0.5] (physical surface 1,
// 2 x 2 cells on either half, conforming along x = 0.5), a block glued on
// the left half of its top (2, [0, 0.5] x [0.5, 1], n x n cells) and one
// resting on the right half (3, [0.5, 1] x [0.5, 1], n x n), each upper
// block meshed on its own (non-matching with the base, its own nodes
// where the two touch at x = 0.5). The base's node at (0.5, 0.5) ends both
// master surfaces. Set n with -setnumber (default 3).
// Boundary ids: 1 the upper blocks' tops y = 1, 2 the base's bottom y = 0,
// 3 the base's top left (tied master), 4 the glued block's bottom (tied
// slave), 5 the base's top right (contact master), 6 the resting block's
// bottom (contact slave), 7 the left sides x = 0 (base, glued block), 8
// the resting block's right side x = 1.
//   gmsh -2 meshes/tied_contact_shared_master_2d.geo -o out.msh
Geometry.AutoCoherence = 0;   // each block keeps its own nodes
Mesh.MshFileVersion    = 2.2;
If (!Exists(n)) n = 3; EndIf

// The base: two quadrilateral surfaces sharing the line x = 0.5.
Point(1) = {0, 0, 0};
Point(2) = {0.5, 0, 0};
Point(3) = {1, 0, 0};
Point(4) = {1, 0.5, 0};
Point(5) = {0.5, 0.5, 0};
Point(6) = {0, 0.5, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 5};
Line(5) = {5, 6};
Line(6) = {6, 1};
Line(7) = {2, 5};
Curve Loop(1) = {1, 7, 5, 6};
Plane Surface(1) = {1};
Curve Loop(2) = {2, 3, 4, -7};
Plane Surface(2) = {2};
Transfinite Curve{1, 2, 3, 4, 5, 6, 7} = 3;
Transfinite Surface{1, 2};
Recombine Surface{1, 2};

// The upper blocks, each with its own points.
For block In {0:1}
  o = 10 + 10 * block;
  x = 0.5 * block;
  Point(o + 1) = {x, 0.5, 0};
  Point(o + 2) = {x + 0.5, 0.5, 0};
  Point(o + 3) = {x + 0.5, 1, 0};
  Point(o + 4) = {x, 1, 0};
  Line(o + 1) = {o + 1, o + 2};  // bottom
  Line(o + 2) = {o + 2, o + 3};  // right
  Line(o + 3) = {o + 3, o + 4};  // top
  Line(o + 4) = {o + 4, o + 1};  // left
  Curve Loop(o + 1) = {o + 1, o + 2, o + 3, o + 4};
  Plane Surface(o + 1) = {o + 1};
  Transfinite Curve{o + 1, o + 2, o + 3, o + 4} = n + 1;
  Transfinite Surface{o + 1};
  Recombine Surface{o + 1};
EndFor

Physical Surface(1) = {1, 2};
Physical Surface(2) = {11};
Physical Surface(3) = {21};
Physical Curve(1) = {13, 23};
Physical Curve(2) = {1, 2};
Physical Curve(3) = {5};
Physical Curve(4) = {11};
Physical Curve(5) = {4};
Physical Curve(6) = {21};
Physical Curve(7) = {6, 14};
Physical Curve(8) = {22};
