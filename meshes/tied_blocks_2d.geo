// tied_blocks_2d.geo - two blocks glued by mesh tying (Contact/Tied pairs),
// meshed on their own so that the interface is non-matching: the lower
// block (physical surface 1) below the interface, the upper one (2) above
// it, together the unit square [0, 1] x [0, 1]. The interface runs from
// (0, 0.5 - tilt) to (1, 0.5 + tilt) (tilt = 0: horizontal).
// Set with -setnumber:
//   nl, nu: cells along each side of the lower and upper block (default 3, 4),
//   tilt:   see above (default 0),
//   free:   1 = the upper block unstructured (quadrilaterals recombined,
//           size 1 / nu) instead of nu x nu cells (default 0).
// Boundary ids: 1 top (y = 1), 2 bottom (y = 0), 3 the lower block's side
// of the interface, 4 the upper block's, 5 the left sides x = 0, 6 the right
// sides x = 1 (both blocks).
//   gmsh -2 -setnumber nl 3 -setnumber nu 4 meshes/tied_blocks_2d.geo -o out.msh
Geometry.AutoCoherence = 0;   // the blocks keep their own nodes on the interface
Mesh.MshFileVersion    = 2.2;
If (!Exists(nl)) nl = 3; EndIf
If (!Exists(nu)) nu = 4; EndIf
If (!Exists(tilt)) tilt = 0; EndIf
If (!Exists(free)) free = 0; EndIf

For body In {0:1}
  o  = 10 * body;             // 0: lower, 10: upper
  Point(o + 1) = {0, body == 0 ? 0 : 0.5 - tilt, 0, 1. / nu};
  Point(o + 2) = {1, body == 0 ? 0 : 0.5 + tilt, 0, 1. / nu};
  Point(o + 3) = {1, body == 0 ? 0.5 + tilt : 1, 0, 1. / nu};
  Point(o + 4) = {0, body == 0 ? 0.5 - tilt : 1, 0, 1. / nu};
  Line(o + 1) = {o + 1, o + 2};  // bottom
  Line(o + 2) = {o + 2, o + 3};  // right
  Line(o + 3) = {o + 3, o + 4};  // top
  Line(o + 4) = {o + 4, o + 1};  // left
  Curve Loop(o + 1) = {o + 1, o + 2, o + 3, o + 4};
  Plane Surface(o + 1) = {o + 1};
  Physical Surface(1 + body) = {o + 1};
EndFor
Transfinite Curve{1, 2, 3, 4} = nl + 1;
Transfinite Surface{1};
If (free == 0)
  Transfinite Curve{11, 12, 13, 14} = nu + 1;
  Transfinite Surface{11};
EndIf
Recombine Surface{1, 11};
Physical Curve(1) = {13};       // top
Physical Curve(2) = {1};        // bottom
Physical Curve(3) = {3};        // the lower block's side of the interface
Physical Curve(4) = {11};       // the upper block's side
Physical Curve(5) = {4, 14};    // left sides
Physical Curve(6) = {2, 12};    // right sides
