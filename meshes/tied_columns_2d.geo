// tied_columns_2d.geo - two separate columns, each two blocks glued by mesh
// tying (Contact/Tied pairs), for the tied release in tension: one column
// is pressed, the other pulled. Each column is a lower block (physical
// surface 1) [x0, x0 + 1] x [0, 0.5] and an upper block (2) [x0, x0 + 1] x
// [0.5, 1], with x0 = 0 (left column) and x0 = 1.5 (right column), meshed on
// their own (nl x nl and nu x nu cells) so that the interfaces y = 0.5 are
// non-matching.
// Set with -setnumber: nl, nu (default 3, 4).
// Boundary ids: 1 top of the left column, 7 top of the right column, 2 the
// bottoms, 3 the lower blocks' side of the interfaces, 4 the upper blocks'
// side, 5 the other sides.
//   gmsh -2 meshes/tied_columns_2d.geo -o meshes/tied_columns_2d.msh
Geometry.AutoCoherence = 0;   // the blocks keep their own nodes on the interface
Mesh.MshFileVersion    = 2.2;
If (!Exists(nl)) nl = 3; EndIf
If (!Exists(nu)) nu = 4; EndIf

For column In {0:1}
  For body In {0:1}
    o  = 20 * column + 10 * body;
    x0 = 1.5 * column;
    y0 = 0.5 * body;
    Point(o + 1) = {x0, y0, 0, 1.};
    Point(o + 2) = {x0 + 1, y0, 0, 1.};
    Point(o + 3) = {x0 + 1, y0 + 0.5, 0, 1.};
    Point(o + 4) = {x0, y0 + 0.5, 0, 1.};
    Line(o + 1) = {o + 1, o + 2};  // bottom
    Line(o + 2) = {o + 2, o + 3};  // right
    Line(o + 3) = {o + 3, o + 4};  // top
    Line(o + 4) = {o + 4, o + 1};  // left
    Curve Loop(o + 1) = {o + 1, o + 2, o + 3, o + 4};
    Plane Surface(o + 1) = {o + 1};
    n = body == 0 ? nl : nu;
    Transfinite Curve{o + 1, o + 2, o + 3, o + 4} = n + 1;
    Transfinite Surface{o + 1};
    Recombine Surface{o + 1};
  EndFor
EndFor
Physical Surface(1) = {1, 21};
Physical Surface(2) = {11, 31};
Physical Curve(1) = {13};
Physical Curve(7) = {33};
Physical Curve(2) = {1, 21};
Physical Curve(3) = {3, 23};
Physical Curve(4) = {11, 31};
Physical Curve(5) = {2, 4, 12, 14, 22, 24, 32, 34};
