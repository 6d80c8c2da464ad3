// pin.geo - a steel pin (a half-disc, radius 1) pressed into a matching
// groove (radius 1.05) of an aluminium plate, plane strain: the example of
// doc/own_scene.md. Millimetres.
//   pin:   centre (0, 1), radius R1 = 1, its flat side y = 1 on top
//   plate: x in [-3, 3], y in [-2, 0.6], the groove a circle of radius
//          R2 = 1.05 about (0, 1.05) cut from its top; pin and groove touch
//          at the origin
// Physical names (contact_fem reads them wherever an id is expected):
//   surfaces "pin", "plate" (bodies); curves "pin top", "pin arc",
//   "groove", "plate top" (the flat parts beside the groove), "plate base";
//   the plate's sides get no name (free).
// Generate: gmsh -2 -format msh22 meshes/pin.geo -o meshes/pin.msh
// (the stored .msh was made with Debian 12's gmsh 4.8.4).
Geometry.AutoCoherence = 0;     // pin and plate touch at the origin but share no node
Mesh.RecombineAll      = 1;     // quadrilaterals (triangles would be split on reading)
Mesh.MshFileVersion    = 2.2;

R1 = 1;       // pin radius
R2 = 1.05;    // groove radius
t  = 0.6;     // height of the plate's top above the bottom of the groove
h_fine = 0.04;  // element size at the contact
h_far  = 0.3;   // element size away from it

// Pin (entities 1..): its arc split at the point of contact.
Point(1) = {0, R1, 0, h_far};          // centre
Point(2) = {-R1, R1, 0, h_far};
Point(3) = { R1, R1, 0, h_far};
Point(4) = {0, 0, 0, h_fine};          // lowest point
Circle(1) = {2, 1, 4};
Circle(2) = {4, 1, 3};
Line(3)   = {3, 2};                    // flat top
Curve Loop(1) = {1, 2, 3};
Plane Surface(1) = {1};

// Plate (entities 11..).
w = Sqrt(R2^2 - (R2 - t)^2);          // half width of the groove at the top
Point(11) = {0, R2, 0};                // centre of the groove
Point(12) = {0, 0, 0, h_fine};         // bottom of the groove
Point(13) = { w, t, 0, h_fine};
Point(14) = {-w, t, 0, h_fine};
Point(15) = { 3, t, 0, h_far};
Point(16) = {-3, t, 0, h_far};
Point(17) = { 3, -2, 0, h_far};
Point(18) = {-3, -2, 0, h_far};
Circle(11) = {14, 11, 12};
Circle(12) = {12, 11, 13};
Line(13) = {13, 15};
Line(14) = {15, 17};
Line(15) = {17, 18};                   // base
Line(16) = {18, 16};
Line(17) = {16, 14};
Curve Loop(11) = {11, 12, 13, 14, 15, 16, 17};
Plane Surface(11) = {11};

Physical Surface("pin", 1)   = {1};
Physical Surface("plate", 2) = {11};
Physical Curve("pin top", 1)    = {3};
Physical Curve("plate base", 2) = {15};
Physical Curve("pin arc", 3)    = {1, 2};
Physical Curve("groove", 4)     = {11, 12};
Physical Curve("plate top", 5)  = {13, 17};
