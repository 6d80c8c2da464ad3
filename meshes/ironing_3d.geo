// ironing_3d.geo - 3D ironing (issue 29, item 4), after Puso and Laursen's
// example: a stiff die, a half cylinder of radius 3 and width 5.2, on a soft
// slab 9 x 4 x 3. Consistent units. All hexahedra: the x-z section is
// meshed with quadrilaterals and extruded along y.
//   slab: x in [-4.5, 4.5], y in [0, 4], z in [0, 3], structured, nx x ny x
//         nz cells graded towards the top (element length h along x; 9 x 2
//         x 2 cells at the default h = 1, ny = 2)
//   die:  a half cylinder of radius 3, axis along y through (xc, *, 6),
//         y in [-0.6, 4.6] (it overhangs both sides of the slab by 0.6), its
//         flat side z = 6 on top; its lowest line touches the slab top
//         along x = xc. Its arc has the element length h throughout (the
//         contact reaches about 60 degrees from the bottom at a press of 1.4)
// Physical names (contact_fem reads them wherever an id is expected):
//   volumes "die", "slab"; surfaces "die top", "die arc", "slab top",
//   "slab base"; the other faces get no name (free).
// Generate (the stored meshes were made with Debian 12's gmsh 4.8.4):
//   gmsh -3 -format msh22 meshes/ironing_3d.geo -o meshes/ironing_3d.msh
// (-setnumber h 0.5 -setnumber ny 4 for a finer one; the scenes refine the
// stored mesh globally instead, a cylinder manifold on the die arc).
Geometry.AutoCoherence = 0;     // die and slab touch but share no node
Mesh.RecombineAll      = 1;     // quadrilaterals in the section
Mesh.MshFileVersion    = 2.2;

DefineConstant[ h = 1, ny = 2 ];
R  = 3;       // die radius
W  = 5.2;     // die width (along y)
xc = -2;      // die axis x at the start (slid by +4 to x = 2)
L  = 9;       // slab length (x)
B  = 4;       // slab width (y)
H  = 3;       // slab height (z)
nx = Round(L/h);
nz = Round(H/h/2);   // graded: about h at the top

// Die section in the plane y = -(W - B)/2, arc split at its lowest point.
y0 = -(W - B)/2;
Point(1) = {xc, y0, H + R, 2*h};                        // axis
Point(2) = {xc - R, y0, H + R, 2*h};
Point(3) = {xc, y0, H, h};                              // lowest point
Point(4) = {xc + R, y0, H + R, 2*h};
Circle(1) = {2, 1, 3};
Circle(2) = {3, 1, 4};
Line(3)   = {4, 2};                                     // flat top
Curve Loop(1) = {1, 2, 3};
Plane Surface(1) = {1};
Transfinite Curve{1, 2} = Round(Pi/2*R/h) + 1;

// Slab section in the plane y = 0, structured.
Point(11) = {-L/2, 0, 0};
Point(12) = { L/2, 0, 0};
Point(13) = { L/2, 0, H};
Point(14) = {-L/2, 0, H};
Line(11) = {11, 12};                                    // base
Line(12) = {12, 13};
Line(13) = {13, 14};                                    // top
Line(14) = {14, 11};
Curve Loop(11) = {11, 12, 13, 14};
Plane Surface(11) = {11};
Transfinite Curve{11, 13} = nx + 1;
Transfinite Curve{12} = nz + 1 Using Progression 0.8;
Transfinite Curve{14} = nz + 1 Using Progression 1/0.8;
Transfinite Surface{11};
// Extruded after both sections are defined (the extrusions number their new
// entities past the largest tag). die[0]: the far end face, die[1]: the
// volume, die[2..4]: the faces swept by curves 1, 2, 3; slab[] likewise.
die[]  = Extrude {0, W, 0} { Surface{1}; Layers{Round(W/B*ny)}; Recombine; };
slab[] = Extrude {0, B, 0} { Surface{11}; Layers{ny}; Recombine; };

Physical Volume("die", 1)         = {die[1]};
Physical Volume("slab", 2)        = {slab[1]};
Physical Surface("die top", 1)    = {die[4]};
Physical Surface("slab base", 2)  = {slab[2]};
Physical Surface("die arc", 3)    = {die[2], die[3]};
Physical Surface("slab top", 4)   = {slab[4]};
