// An O-ring section pressed between two plates: plane strain, a quarter by symmetry (x = 0 and
// the seal's horizontal diameter y = 0). The seal: a disc of radius 5 mm; the plate: a steel
// bar 8 x 1 mm resting on the seal's top. Quadrangles (recombined), 0.25 mm on the seal.
// Regenerate seal.msh with make_mesh.sh.
r = 0.005;
h = 0.00025;
Point(1) = {0, 0, 0, h};
Point(2) = {r, 0, 0, h};
Point(3) = {0, r, 0, h};
Line(1) = {1, 2};
Circle(2) = {2, 1, 3};
Line(3) = {3, 1};
Curve Loop(1) = {1, 2, 3};
Plane Surface(1) = {1};

w = 0.008;
t = 0.001;
hp = 0.0005;
Point(4) = {0, r, 0, hp};
Point(5) = {w, r, 0, hp};
Point(6) = {w, r + t, 0, hp};
Point(7) = {0, r + t, 0, hp};
Line(4) = {4, 5};
Line(5) = {5, 6};
Line(6) = {6, 7};
Line(7) = {7, 4};
Curve Loop(2) = {4, 5, 6, 7};
Plane Surface(2) = {2};
Transfinite Curve{4, 6} = 17;
Transfinite Curve{5, 7} = 3;
Transfinite Surface{2};

Recombine Surface{1, 2};
Mesh.Algorithm = 6; // frontal-Delaunay, then recombined
Mesh.RecombinationAlgorithm = 1;

Physical Surface("seal") = {1};
Physical Surface("plate") = {2};
Physical Curve("seal_symmetry") = {1};
Physical Curve("seal_surface") = {2};
Physical Curve("seal_axis") = {3};
Physical Curve("plate_bottom") = {4};
Physical Curve("plate_top") = {6};
Physical Curve("plate_axis") = {7};
