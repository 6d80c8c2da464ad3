// friction_block_fillet.geo - the sliding block of
// tests/scenes/current_kinematics_friction_01 / finite_strain_spr_friction_
// adaptive_01 (issue 29: the 'contact blocks' scene, Width 4, Height 1,
// refined once) with the master's leading corner rounded: a circular fillet
// of radius r about (4 - r, 1 - r) between the master's top and its right
// side. Plane strain, consistent units.
//   upper (slave) block: [0, 4] x [1, 2], ns x ns structured cells (ns =
//          4 / hs), as the generator's 8 x 8 refined once for hs = 0.25
//          (cells 0.25 x 0.0625);
//   lower (master) block: [0, 4] x [0, 1] less the fillet, unstructured
//          quadrilaterals of size hm, the arc in n straight facets.
// r = 0 gives the square corner (the generator's scene on another master
// mesh). The fillet shares boundary id 4 with the flat top (a pair has one
// master id), so it cannot carry a circle manifold (Geometry/Manifolds
// takes whole boundary ids): the arc is its n chords, and the scene is run
// without refinement. doc/finite_strain.md, "The slip front: a rounded
// master corner".
// Physical names: surfaces "upper" (1), "lower" (2); curves "upper top"
// (1), "lower base" (2), "upper bottom" (3, the slave), "lower top" (4, the
// master: flat top and fillet); the sides get no name (free).
// Generate (Debian 12's gmsh 4.8.4):
//   gmsh -2 -setnumber r 0.5 meshes/friction_block_fillet.geo \
//        -o meshes/friction_block_fillet_r0.5.msh
// and check that no triangle is left (contact_fem would split every cell).
Geometry.AutoCoherence = 0;     // the blocks touch but share no node
Mesh.RecombineAll      = 1;     // quadrilaterals
Mesh.MshFileVersion    = 2.2;

DefineConstant[ r = 0.5, n = 8, hm = 0.2, hs = 0.25 ];
W = 4;
H = 1;

// Lower (master) block.
Point(1) = {0, 0, 0, hm};
Point(2) = {W, 0, 0, hm};
If (r > 0 && r < H)
  Point(3) = {W, H - r, 0, hm};
EndIf
If (r > 0)
  Point(4) = {W - r, H, 0, hm};
  Point(5) = {W - r, H - r, 0, hm};       // fillet centre
Else
  Point(4) = {W, H, 0, hm};
EndIf
Point(6) = {0, H, 0, hm};
Line(1) = {1, 2};                         // base
If (r > 0)
  If (r < H)
    Line(2) = {2, 3};                     // right side below the fillet
    Circle(3) = {3, 5, 4};
  Else
    Circle(3) = {2, 5, 4};
  EndIf
  Transfinite Curve{3} = n + 1;
Else
  Line(2) = {2, 4};
EndIf
Line(4) = {4, 6};                         // flat top
Line(5) = {6, 1};
If (r > 0 && r < H)
  Curve Loop(1) = {1, 2, 3, 4, 5};
ElseIf (r > 0)
  Curve Loop(1) = {1, 3, 4, 5};
Else
  Curve Loop(1) = {1, 2, 4, 5};
EndIf
Plane Surface(1) = {1};

// Upper (slave) block, structured.
ns = Round(W / hs);
Point(11) = {0, H, 0};
Point(12) = {W, H, 0};
Point(13) = {W, 2*H, 0};
Point(14) = {0, 2*H, 0};
Line(11) = {11, 12};                      // bottom (slave)
Line(12) = {12, 13};
Line(13) = {13, 14};                      // top (driven)
Line(14) = {14, 11};
Curve Loop(11) = {11, 12, 13, 14};
Plane Surface(11) = {11};
Transfinite Curve{11, 12, 13, 14} = ns + 1;
Transfinite Surface{11};

Physical Surface("upper", 1)      = {11};
Physical Surface("lower", 2)      = {1};
Physical Curve("upper top", 1)    = {13};
Physical Curve("lower base", 2)   = {1};
Physical Curve("upper bottom", 3) = {11};
If (r > 0)
  Physical Curve("lower top", 4)  = {3, 4};
Else
  Physical Curve("lower top", 4)  = {4};
EndIf
