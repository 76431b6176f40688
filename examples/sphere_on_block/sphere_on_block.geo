// Sphere on block: a punch with a spherical bottom (a square column whose lower face lies on a
// sphere of radius R) resting on a flat block, quarter model with the symmetry planes x = 0 and
// y = 0. All-hexahedral structured mesh (transfinite volumes, recombined surfaces), graded
// towards the first contact point at the origin. Units: metres (feticon works in SI).
// Regenerate: ./make_mesh.sh  (gmsh -3 -format msh41 sphere_on_block.geo -o sphere_on_block.msh)

SetFactory("Built-in");

// ---- parameters ------------------------------------------------------------------------------
R = 0.05;     // sphere radius of the punch's lower face (m)
a = 0.01;     // punch half-width: the quarter punch spans [0, a] x [0, a] (m)
H = 0.012;    // punch top height above the lowest point z = 0 (m)
b = 0.02;     // block half-width: the quarter block spans [0, b] x [0, b] (m)
d = 0.01;     // block depth: the block spans z in [-d, 0] (m)

n_punch = 14;    // punch cells along x and y
n_punch_z = 10;  // punch cells along z
n_base = 16;     // block cells along x and y
n_base_z = 10;   // block cells along z
// Geometric growth of consecutive cells away from the origin (first cells about 0.3-0.45 mm).
r_punch = 1.12;
r_base = 1.167;
r_z = 1.2;

// ---- punch: corners on the sphere centred at (0, 0, R), touching the block at the origin ------
Point(1) = {0, 0, 0};
Point(2) = {a, 0, R - Sqrt(R^2 - a^2)};
Point(3) = {a, a, R - Sqrt(R^2 - 2 * a^2)};
Point(4) = {0, a, R - Sqrt(R^2 - a^2)};
Point(5) = {0, 0, H};
Point(6) = {a, 0, H};
Point(7) = {a, a, H};
Point(8) = {0, a, H};
Point(9) = {0, 0, R};   // sphere centre
Point(10) = {a, 0, R};  // centre of the small circle sphere ^ {x = a}
Point(11) = {0, a, R};  // centre of the small circle sphere ^ {y = a}

// Curves run from small to large coordinates so that parallel edges grade alike.
Circle(1) = {1, 9, 2};   // x-direction, y = 0
Circle(2) = {4, 11, 3};  // x-direction, y = a
Line(3) = {5, 6};
Line(4) = {8, 7};
Circle(5) = {1, 9, 4};   // y-direction, x = 0
Circle(6) = {2, 10, 3};  // y-direction, x = a
Line(7) = {5, 8};
Line(8) = {6, 7};
Line(9) = {1, 5};        // z-direction, bottom to top
Line(10) = {2, 6};
Line(11) = {3, 7};
Line(12) = {4, 8};

Curve Loop(1) = {1, 6, -2, -5};    // bottom, on the sphere
Surface(1) = {1} In Sphere {9};
Curve Loop(2) = {3, 8, -4, -7};    // top z = H
Plane Surface(2) = {2};
Curve Loop(3) = {1, 10, -3, -9};   // y = 0
Plane Surface(3) = {3};
Curve Loop(4) = {6, 11, -8, -10};  // x = a
Plane Surface(4) = {4};
Curve Loop(5) = {2, 11, -4, -12};  // y = a
Plane Surface(5) = {5};
Curve Loop(6) = {5, 12, -7, -9};   // x = 0
Plane Surface(6) = {6};
Surface Loop(1) = {1, 2, 3, 4, 5, 6};
Volume(1) = {1};

Transfinite Curve{1, 2, 3, 4, 5, 6, 7, 8} = n_punch + 1 Using Progression r_punch;
Transfinite Curve{9, 10, 11, 12} = n_punch_z + 1 Using Progression r_z;
Transfinite Surface{1, 2, 3, 4, 5, 6};
Recombine Surface{1, 2, 3, 4, 5, 6};
Transfinite Volume{1} = {1, 2, 3, 4, 5, 6, 7, 8};

// ---- block [0, b] x [0, b] x [-d, 0]: its own points, so the bodies share no nodes ------------
Point(21) = {0, 0, 0};
Point(22) = {b, 0, 0};
Point(23) = {b, b, 0};
Point(24) = {0, b, 0};
Point(25) = {0, 0, -d};
Point(26) = {b, 0, -d};
Point(27) = {b, b, -d};
Point(28) = {0, b, -d};

Line(21) = {21, 22};  // x-direction
Line(22) = {24, 23};
Line(23) = {25, 26};
Line(24) = {28, 27};
Line(25) = {21, 24};  // y-direction
Line(26) = {22, 23};
Line(27) = {25, 28};
Line(28) = {26, 27};
Line(29) = {21, 25};  // z-direction, top to bottom (fine cells at the contact surface)
Line(30) = {22, 26};
Line(31) = {23, 27};
Line(32) = {24, 28};

Curve Loop(21) = {21, 26, -22, -25};  // top z = 0
Plane Surface(21) = {21};
Curve Loop(22) = {23, 28, -24, -27};  // bottom z = -d
Plane Surface(22) = {22};
Curve Loop(23) = {21, 30, -23, -29};  // y = 0
Plane Surface(23) = {23};
Curve Loop(24) = {26, 31, -28, -30};  // x = b
Plane Surface(24) = {24};
Curve Loop(25) = {22, 31, -24, -32};  // y = b
Plane Surface(25) = {25};
Curve Loop(26) = {25, 32, -27, -29};  // x = 0
Plane Surface(26) = {26};
Surface Loop(21) = {21, 22, 23, 24, 25, 26};
Volume(21) = {21};

Transfinite Curve{21, 22, 23, 24, 25, 26, 27, 28} = n_base + 1 Using Progression r_base;
Transfinite Curve{29, 30, 31, 32} = n_base_z + 1 Using Progression r_z;
Transfinite Surface{21, 22, 23, 24, 25, 26};
Recombine Surface{21, 22, 23, 24, 25, 26};
Transfinite Volume{21} = {21, 22, 23, 24, 25, 26, 27, 28};

// ---- physical groups: bodies, and the face sets named in problem.yaml -------------------------
Physical Volume("punch") = {1};
Physical Volume("base") = {21};
Physical Surface("punch_contact") = {1};   // spherical lower face of the punch
Physical Surface("punch_top") = {2};       // loaded face z = H
Physical Surface("base_contact") = {21};   // top of the block z = 0
Physical Surface("base_bottom") = {22};    // supported face z = -d
Physical Surface("symmetry_x") = {6, 26};  // plane x = 0, both bodies
Physical Surface("symmetry_y") = {3, 23};  // plane y = 0, both bodies

Mesh.MshFileVersion = 4.1;
Mesh.SaveAll = 0;  // only elements of physical groups
