// Sphere on block from CAD: the punch of examples/sphere_on_block (a square column whose lower
// face lies on a sphere of radius R) drawn as OpenCASCADE solids, a box cut by a ball, and
// meshed by Gmsh with 10-node tetrahedra graded towards the first contact point at the origin.
// Quarter model with the symmetry planes x = 0 and y = 0. Units: metres (feticon works in SI).
// Regenerate: ./make_mesh.sh  (gmsh -3 -format msh41 sphere_on_block_tet10.geo -o ...msh)

SetFactory("OpenCASCADE");

// ---- parameters (those of examples/sphere_on_block) --------------------------------------------
R = 0.05;     // sphere radius of the punch's lower face (m)
a = 0.01;     // punch half-width: the quarter punch spans [0, a] x [0, a] (m)
H = 0.012;    // punch top height above the lowest point z = 0 (m)
b = 0.02;     // block half-width: the quarter block spans [0, b] x [0, b] (m)
d = 0.01;     // block depth: the block spans z in [-d, 0] (m)
h_contact = 0.00035;  // element size within r_fine of the origin (the contact radius is ~1.9 mm)
growth = 0.12;        // size increase per metre of distance from the origin
h_far = 0.002;        // the largest element size

// ---- solids ------------------------------------------------------------------------------------
Box(1) = {0, 0, 0, a, a, H};
Sphere(2) = {0, 0, R, R};
// Turn the ball's poles (and the degenerate edge there) away from the contact point at its
// bottom: to (+-R sin 45, +-R cos 45, R) outside the quarter punch.
Rotate {{1, 0, 0}, {0, 0, R}, Pi / 2} { Volume{2}; }
Rotate {{0, 0, 1}, {0, 0, R}, Pi / 4} { Volume{2}; }
punch() = BooleanIntersection{ Volume{1}; Delete; }{ Volume{2}; Delete; };
Box(3) = {0, 0, -d, b, b, d};
base = 3;

// ---- groups: bodies, and the faces feticon names in problem.yaml ---------------------------------
eps = 1e-7;
Physical Volume("punch") = {punch()};
Physical Volume("base") = {base};
// The spherical face: the punch's faces less its planar ones (OpenCASCADE bounds a spherical
// patch by its whole sphere, so no bounding box picks it alone).
contact() = Abs(Boundary{ Volume{punch()}; });
contact() -= Surface In BoundingBox{-eps, -2 * R, -2 * R, eps, 2 * R, 2 * R};          // x = 0
contact() -= Surface In BoundingBox{-2 * R, -eps, -2 * R, 2 * R, eps, 2 * R};          // y = 0
contact() -= Surface In BoundingBox{a - eps, -2 * R, -2 * R, a + eps, 2 * R, 2 * R};   // x = a
contact() -= Surface In BoundingBox{-2 * R, a - eps, -2 * R, 2 * R, a + eps, 2 * R};   // y = a
contact() -= Surface In BoundingBox{-eps, -eps, H - eps, a + eps, a + eps, H + eps};   // top
Physical Surface("punch_contact") = {contact()};
Physical Surface("punch_top") = Surface In BoundingBox{-eps, -eps, H - eps, a + eps, a + eps, H + eps};
Physical Surface("base_contact") = Surface In BoundingBox{-eps, -eps, -eps, b + eps, b + eps, eps};
Physical Surface("base_bottom") = Surface In BoundingBox{-eps, -eps, -d - eps, b + eps, b + eps, -d + eps};
// Boxes reach below z = 0 and above H: OpenCASCADE bounds a face with a circular edge by the
// circle's box.
Physical Surface("symmetry_x") = Surface In BoundingBox{-eps, -2 * R, -2 * R, eps, 2 * R, 2 * R};
Physical Surface("symmetry_y") = Surface In BoundingBox{-2 * R, -eps, -2 * R, 2 * R, eps, 2 * R};

// ---- mesh: sizes graded with the distance from the origin, second order ------------------------
// h(r) = h_contact + growth r, at most h_far: Gmsh grows the elements with the distance r.
Field[1] = MathEval;
Field[1].F = Sprintf("Min(%g + %g * Sqrt(x^2 + y^2 + z^2), %g)", h_contact, growth, h_far);
Background Field = 1;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
Mesh.ElementOrder = 2;
Mesh.HighOrderOptimize = 0;
Mesh.Algorithm3D = 1;
