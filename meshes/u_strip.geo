// A U-shaped body (2D, one material): two prongs of width 1 and height 2 on
// a base of height 1, 0.2 apart. Pushing the top of the left prong to the
// right folds the body onto itself (the prong enters the right one).
// Boundary ids: 1 the base's bottom, 2 the left prong's top; the rest 0.
// gmsh -2 -format msh22 u_strip.geo -o u_strip.msh
n = 4;      // cells across a prong (h = 0.25)
Point(1) = {0, 0, 0};   Point(2) = {1, 0, 0};   Point(3) = {1.2, 0, 0};  Point(4) = {2.2, 0, 0};
Point(5) = {0, 1, 0};   Point(6) = {1, 1, 0};   Point(7) = {1.2, 1, 0};  Point(8) = {2.2, 1, 0};
Point(9) = {0, 3, 0};   Point(10) = {1, 3, 0};  Point(11) = {1.2, 3, 0}; Point(12) = {2.2, 3, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4};
Line(4) = {5, 6}; Line(5) = {6, 7}; Line(6) = {7, 8};
Line(7) = {9, 10}; Line(8) = {11, 12};
Line(9) = {1, 5}; Line(10) = {2, 6}; Line(11) = {3, 7}; Line(12) = {4, 8};
Line(13) = {5, 9}; Line(14) = {6, 10}; Line(15) = {7, 11}; Line(16) = {8, 12};
Curve Loop(1) = {1, 10, -4, -9};   Plane Surface(1) = {1};
Curve Loop(2) = {2, 11, -5, -10};  Plane Surface(2) = {2};
Curve Loop(3) = {3, 12, -6, -11};  Plane Surface(3) = {3};
Curve Loop(4) = {4, 14, -7, -13};  Plane Surface(4) = {4};
Curve Loop(5) = {6, 16, -8, -15};  Plane Surface(5) = {5};
Transfinite Curve {1, 3, 4, 6, 7, 8, 9, 10, 11, 12} = n + 1;
Transfinite Curve {2, 5} = 2;
Transfinite Curve {13, 14, 15, 16} = 2 * n + 1;
Transfinite Surface {1, 2, 3, 4, 5};
Recombine Surface {1, 2, 3, 4, 5};
Physical Surface(1) = {1, 2, 3, 4, 5};
Physical Curve(1) = {1, 2, 3};
Physical Curve(2) = {7};
Physical Curve(3) = {5, 8, 9, 12, 13, 14, 15, 16};
