// contact_chain_3d.geo - the chain of contact pairs of contact_chain_2d.geo
// in 3D: its three bodies extruded along z from 0 to 1, in hexahedra, with
// a different number of layers in the middle body, so that both pairs are
// non-matching across the depth too. A base L (0..2 x 0..0.5 x 0..1,
// 4 x 1 x 2 cells), a block M on its left half (0..1 x 0.5..1, 2 x 2 x 3
// cells) and a block R beside M (1..2 x 0.55..1.05, 1 x 8 x 2 cells),
// clear of the base by 0.05. M's bottom is a slave on L's top, R's left
// side a slave on M's right side: the nodes of M's edge (1, 0.5, z) are
// slaves of the first pair and masters of the second.
// Boundary ids as in 2D: 1 L's bottom, 2 L's top, 3 M's bottom, 4 M's
// right side, 5 R's left side, 6 M's top, 7 R's right side, 8 M's left
// side, 9 R's top, 10 R's bottom; 11 the faces z = 0, 12 the faces z = 1
// (of every body). Material ids 1 (L), 2 (M), 3 (R).
//   gmsh -3 meshes/contact_chain_3d.geo -o meshes/contact_chain_3d.msh
Geometry.AutoCoherence = 0;   // each body keeps its own nodes
Mesh.MshFileVersion    = 2.2;
x0[] = {0, 0, 1};
x1[] = {2, 1, 2};
y0[] = {0, 0.5, 0.55};
y1[] = {0.5, 1, 1.05};
nx[] = {4, 2, 1};
ny[] = {1, 2, 8};
nz[] = {2, 3, 2};
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
EndFor
// Extruded once every body's face exists: the extrusion numbers its new
// entities after the largest id.
For body In {0:2}
  // out[0] the face z = 1, out[1] the volume, out[2..5] the sides swept
  // from the bottom, right, top and left lines.
  out[] = Extrude {0, 0, 1} { Surface{10 * body + 1}; Layers{nz[body]}; Recombine; };
  top[body] = out[0];
  volume[body] = out[1];
  bottom[body] = out[2];
  right[body] = out[3];
  up[body] = out[4];
  left[body] = out[5];
  Physical Volume(1 + body) = {out[1]};
EndFor
Physical Surface(1) = {bottom[0]};
Physical Surface(2) = {up[0]};
Physical Surface(3) = {bottom[1]};
Physical Surface(4) = {right[1]};
Physical Surface(5) = {left[2]};
Physical Surface(6) = {up[1]};
Physical Surface(7) = {right[2]};
Physical Surface(8) = {left[1]};
Physical Surface(9) = {up[2]};
Physical Surface(10) = {bottom[2]};
Physical Surface(11) = {1, 11, 21};
Physical Surface(12) = {top[0], top[1], top[2]};
