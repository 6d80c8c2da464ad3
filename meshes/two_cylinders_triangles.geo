// two_cylinders_triangles.geo - the two half-discs of two_cylinders.geo with
// the same nodes on every curve, but meshed with unstructured triangles (no
// transfinite surfaces, no recombination), as a user's first mesh would be;
// contact_fem splits each triangle into 3 quadrilaterals on reading, which
// halves the elements along the arcs (as one refinement of two_cylinders.msh):
//   upper body (physical surface 1): centre (0, R), flat top y = R
//     (physical line 1, loaded), arc below (physical line 3, slave);
//   lower body (physical surface 2): centre (0, -R), flat bottom y = -R
//     (physical line 2, fixed), arc above (physical line 4, master).
// Each half-disc keeps the four patches and the graded curves of
// two_cylinders.geo (arc elements 0.146 long at the origin, R = 8), but the
// patches are filled by Gmsh's default triangulation: 508 triangles per
// body, 1524 quadrilaterals after the split. The two bodies share no node
// (AutoCoherence off).
// Generate: gmsh -2 -format msh22 meshes/two_cylinders_triangles.geo -o meshes/two_cylinders_triangles.msh
// (the stored .msh was made with Debian 12's gmsh 4.8.4).

Geometry.AutoCoherence = 0;
Mesh.MshFileVersion    = 2.2;

R     = 8;        // radius of both half-discs
core  = 0.4375;   // half width of the core patch / R (as the built-in Hertz disc)
depth = 0.5;      // depth of the core patch below the flat side / R
n_arc  = 7;       // elements on each half of the middle arc (and below the core)
n_side = 3;       // elements on each side arc (and across the core)
n_rad  = 6;       // elements from the middle arc to the core
grade_arc = 1.6;  // growth factor of the element length away from the contact
grade_rad = 1.4;  // growth factor away from the arc, toward the core

s = Sqrt(0.5);
For body In {0:1}
  sy = 1 - 2 * body;          // +1: upper body, -1: lower body (mirror image)
  cy = sy * R;                // centre of the disc
  o  = 100 * body;            // entity number offset of the body
  Point(o + 1)  = {0, cy, 0};                   // centre (arcs only)
  Point(o + 2)  = {-R, cy, 0};                  // ends of the flat side
  Point(o + 3)  = { R, cy, 0};
  Point(o + 4)  = {-R * s, cy - sy * R * s, 0}; // ends of the middle arc
  Point(o + 5)  = { R * s, cy - sy * R * s, 0};
  Point(o + 6)  = {0, 0, 0};                    // point of contact
  Point(o + 7)  = {-core * R, cy, 0};           // core corners
  Point(o + 8)  = { core * R, cy, 0};
  Point(o + 9)  = {-core * R, cy - sy * depth * R, 0};
  Point(o + 10) = { core * R, cy - sy * depth * R, 0};
  Point(o + 11) = {0, cy, 0};                   // middle of the flat side
  Point(o + 12) = {0, cy - sy * depth * R, 0};  // middle of the core bottom

  // Arc (boundary 3 or 4), each curve oriented toward the point of contact
  // or away from it, so that one progression grades all of them alike.
  Circle(o + 1) = {o + 2, o + 1, o + 4};        // side arcs
  Circle(o + 2) = {o + 5, o + 1, o + 3};
  Circle(o + 3) = {o + 4, o + 1, o + 6};        // middle arc, toward contact
  Circle(o + 4) = {o + 6, o + 1, o + 5};        // middle arc, away from it
  // Flat side (boundary 1 or 2).
  Line(o + 5) = {o + 2, o + 7};
  Line(o + 6) = {o + 7, o + 11};
  Line(o + 7) = {o + 11, o + 8};
  Line(o + 8) = {o + 8, o + 3};
  // Interior lines.
  Line(o + 9)  = {o + 9, o + 12};               // core bottom, toward the axis
  Line(o + 10) = {o + 12, o + 10};              // and away from it
  Line(o + 11) = {o + 7, o + 9};                // core sides
  Line(o + 12) = {o + 8, o + 10};
  Line(o + 13) = {o + 9, o + 4};                // from the core to the arc
  Line(o + 14) = {o + 10, o + 5};

  Transfinite Curve{o + 3} = n_arc + 1 Using Progression 1 / grade_arc;
  Transfinite Curve{o + 4} = n_arc + 1 Using Progression grade_arc;
  // The core is uniform: graded columns would be slender up to the flat side.
  Transfinite Curve{o + 6, o + 7, o + 9, o + 10} = n_arc + 1;
  Transfinite Curve{o + 1, o + 2, o + 11, o + 12} = n_side + 1;
  // Radial lines, shorter toward the arc.
  Transfinite Curve{o + 8, o + 13, o + 14} = n_rad + 1 Using Progression 1 / grade_rad;
  Transfinite Curve{o + 5} = n_rad + 1 Using Progression grade_rad;

  Curve Loop(o + 1) = {o + 9, o + 10, -(o + 12), -(o + 7), -(o + 6), o + 11}; // core
  Plane Surface(o + 1) = {o + 1};
  Curve Loop(o + 2) = {o + 3, o + 4, -(o + 14), -(o + 10), -(o + 9), o + 13};
  Plane Surface(o + 2) = {o + 2};                                     // middle
  Curve Loop(o + 3) = {o + 1, -(o + 13), -(o + 11), -(o + 5)};        // left
  Plane Surface(o + 3) = {o + 3};
  Curve Loop(o + 4) = {o + 2, -(o + 8), o + 12, o + 14};              // right
  Plane Surface(o + 4) = {o + 4};

  Physical Surface(1 + body)  = {o + 1, o + 2, o + 3, o + 4};
  Physical Curve(1 + body)    = {o + 5, o + 6, o + 7, o + 8}; // flat side: 1 top, 2 bottom
  Physical Curve(3 + body)    = {o + 1, o + 2, o + 3, o + 4}; // arc: 3 upper, 4 lower
EndFor
