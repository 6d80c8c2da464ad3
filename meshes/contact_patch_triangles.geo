// contact_patch_triangles.geo - the contact patch test on a mixed mesh: two
// stacked unit squares, the upper one meshed with unstructured triangles,
// the lower one with unstructured quadrilaterals (recombined), of different
// sizes (non-matching at the interface y = 1). contact_fem splits every
// triangle into 3 and every quadrilateral into 4 quadrilaterals on reading.
//   upper block (physical surface 1): [0, 1] x [1, 2], top y = 2 (line 1,
//     loaded), bottom (line 3, slave);
//   lower block (physical surface 2): [0, 1] x [0, 1], bottom y = 0 (line 2),
//     top (line 4, master); left sides line 5, right sides line 6.
// Generate: gmsh -2 -format msh22 meshes/contact_patch_triangles.geo -o meshes/contact_patch_triangles.msh
Geometry.AutoCoherence = 0;   // the blocks keep their own nodes at y = 1
Mesh.MshFileVersion    = 2.2;

For body In {0:1}
  o = 10 * body;              // 0: upper, 10: lower
  y = 1 - body;               // bottom of the block
  h = 0.3 - 0.12 * body;      // upper 0.3, lower 0.18: non-matching
  Point(o + 1) = {0, y, 0, h};
  Point(o + 2) = {1, y, 0, h};
  Point(o + 3) = {1, y + 1, 0, h};
  Point(o + 4) = {0, y + 1, 0, h};
  Line(o + 1) = {o + 1, o + 2};  // bottom
  Line(o + 2) = {o + 2, o + 3};  // right
  Line(o + 3) = {o + 3, o + 4};  // top
  Line(o + 4) = {o + 4, o + 1};  // left
  Curve Loop(o + 1) = {o + 1, o + 2, o + 3, o + 4};
  Plane Surface(o + 1) = {o + 1};
  Physical Surface(1 + body) = {o + 1};
EndFor
Recombine Surface{11};          // the lower block: quadrilaterals
Physical Curve(1) = {3};        // top of the upper block
Physical Curve(2) = {11};       // bottom of the lower block
Physical Curve(3) = {1};        // slave
Physical Curve(4) = {13};       // master
Physical Curve(5) = {4, 14};    // left sides
Physical Curve(6) = {2, 12};    // right sides
