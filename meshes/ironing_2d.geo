// ironing_2d.geo - 2D ironing (issue 29, item 4): a stiff half-disc die on
// a soft block, plane strain, after Fischer and Wriggers' frictionless
// ironing example (our own dimensions). Consistent units.
//   block: x in [-5, 5], y in [0, 2], 40 x 6 structured quadrilaterals
//          graded towards the top (element length 0.25 along x)
//   die:   a half-disc of radius 1 about (-1.5, 3), its flat side y = 3 on
//          top; its arc touches the block top at (-1.5, 2). The bottom
//          +-60 degrees of the arc, where it touches, have the block top's
//          element length (the block is the slave surface).
// Physical names (contact_fem reads them wherever an id is expected):
//   surfaces "die", "block"; curves "die top", "die arc", "block top",
//   "block base"; the block's sides get no name (free).
// Generate: gmsh -2 -format msh22 meshes/ironing_2d.geo -o meshes/ironing_2d.msh
// (the stored .msh was made with Debian 12's gmsh 4.8.4). The scene refines
// it globally for the finer mesh (Geometry/Global refinements, a circle
// manifold on the die arc).
Geometry.AutoCoherence = 0;     // die and block touch but share no node
Mesh.RecombineAll      = 1;     // quadrilaterals
Mesh.MshFileVersion    = 2.2;

R  = 1;       // die radius
xc = -1.5;    // die centre x at the start
L  = 5;       // block half length
H  = 2;       // block height
nx = 40;      // block cells along x
ny = 6;       // block cells along y
h_fine = 0.25;   // die arc element length where it touches
h_far  = 0.4;    // die element length elsewhere

// Die (entities 1..): arc split at -60, 0 (bottom) and +60 degrees.
Point(1) = {xc, H + R, 0, h_far};                       // centre
Point(2) = {xc - R, H + R, 0, h_far};
Point(3) = {xc - R*Sin(Pi/3), H + R - R*Cos(Pi/3), 0, h_fine};
Point(4) = {xc, H, 0, h_fine};                          // lowest point
Point(5) = {xc + R*Sin(Pi/3), H + R - R*Cos(Pi/3), 0, h_fine};
Point(6) = {xc + R, H + R, 0, h_far};
Circle(1) = {2, 1, 3};
Circle(2) = {3, 1, 4};
Circle(3) = {4, 1, 5};
Circle(4) = {5, 1, 6};
Line(5)   = {6, 2};                                      // flat top
Curve Loop(1) = {1, 2, 3, 4, 5};
Plane Surface(1) = {1};
Transfinite Curve{2, 3} = Round(Pi/3*R/h_fine) + 1;

// Block (entities 11..), structured.
Point(11) = {-L, 0, 0};
Point(12) = { L, 0, 0};
Point(13) = { L, H, 0};
Point(14) = {-L, H, 0};
Line(11) = {11, 12};                                     // base
Line(12) = {12, 13};
Line(13) = {13, 14};                                     // top
Line(14) = {14, 11};
Curve Loop(11) = {11, 12, 13, 14};
Plane Surface(11) = {11};
Transfinite Curve{11, 13} = nx + 1;
Transfinite Curve{12} = ny + 1 Using Progression 0.8;
Transfinite Curve{14} = ny + 1 Using Progression 1/0.8;
Transfinite Surface{11};

Physical Surface("die", 1)        = {1};
Physical Surface("block", 2)      = {11};
Physical Curve("die top", 1)      = {5};
Physical Curve("block base", 2)   = {11};
Physical Curve("die arc", 3)      = {1, 2, 3, 4};
Physical Curve("block top", 4)    = {13};
