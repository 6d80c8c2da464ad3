// Round 7: grazing contact at a corner (2D). Lower block (material 2)
// [0, 1] x [0, 1]; upper block (material 1) [xo, xo + 1] x [1, 2], so its
// bottom overhangs the lower block's corner (1, 1). Quadrilaterals, the
// bodies on their own nodes. Ids: 1 upper top, 2 lower bottom,
// 3 upper bottom (slave), 4 lower top (master).
//   gmsh -2 -setnumber xo 0.5 -setnumber n 7 corner_2d.geo -o corner_2d.msh
If (!Exists(xo))
  xo = 0.5;
EndIf
If (!Exists(n))
  n = 7;
EndIf
Mesh.MshFileVersion = 2.2;
Mesh.RecombineAll = 1;
Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {1, 1, 0}; Point(4) = {0, 1, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Transfinite Curve{1, 2, 3, 4} = n;
Transfinite Surface{1};
Point(5) = {xo, 1, 0}; Point(6) = {xo + 1, 1, 0}; Point(7) = {xo + 1, 2, 0}; Point(8) = {xo, 2, 0};
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 8}; Line(8) = {8, 5};
Curve Loop(2) = {5, 6, 7, 8}; Plane Surface(2) = {2};
Transfinite Curve{5, 6, 7, 8} = n + 2;
Transfinite Surface{2};
Physical Surface(1) = {2};
Physical Surface(2) = {1};
Physical Curve(1) = {7};
Physical Curve(2) = {1};
Physical Curve(3) = {5};
Physical Curve(4) = {3};
