// tied_contact_blocks_2d.geo - tied and contact pairs in one scene: three
// unit-wide blocks 0.5 high stacked on each other, each meshed on its own
// (all interfaces non-matching): the lower one (physical surface 1,
// nl x nl cells), the middle one (2, nm x nm) resting on it (contact) and
// the upper one (3, nu x nu) glued on top of the middle one (mesh tying).
// Set with -setnumber: nl, nm, nu (default 3, 4, 3).
// Boundary ids: 1 top y = 1.5, 2 bottom y = 0, 3 the lower block's top,
// 4 the middle block's bottom, 5 the middle block's top, 6 the upper
// block's bottom, 7 the left sides x = 0, 8 the right sides x = 1.
//   gmsh -2 meshes/tied_contact_blocks_2d.geo -o out.msh
Geometry.AutoCoherence = 0;   // each block keeps its own nodes
Mesh.MshFileVersion    = 2.2;
If (!Exists(nl)) nl = 3; EndIf
If (!Exists(nm)) nm = 4; EndIf
If (!Exists(nu)) nu = 3; EndIf
n[] = {nl, nm, nu};
For body In {0:2}
  o = 10 * body;
  y = 0.5 * body;
  Point(o + 1) = {0, y, 0};
  Point(o + 2) = {1, y, 0};
  Point(o + 3) = {1, y + 0.5, 0};
  Point(o + 4) = {0, y + 0.5, 0};
  Line(o + 1) = {o + 1, o + 2};  // bottom
  Line(o + 2) = {o + 2, o + 3};  // right
  Line(o + 3) = {o + 3, o + 4};  // top
  Line(o + 4) = {o + 4, o + 1};  // left
  Curve Loop(o + 1) = {o + 1, o + 2, o + 3, o + 4};
  Plane Surface(o + 1) = {o + 1};
  Transfinite Curve{o + 1, o + 2, o + 3, o + 4} = n[body] + 1;
  Transfinite Surface{o + 1};
  Recombine Surface{o + 1};
  Physical Surface(1 + body) = {o + 1};
EndFor
Physical Curve(1) = {23};
Physical Curve(2) = {1};
Physical Curve(3) = {3};
Physical Curve(4) = {11};
Physical Curve(5) = {13};
Physical Curve(6) = {21};
Physical Curve(7) = {4, 14, 24};
Physical Curve(8) = {2, 12, 22};
