// Tiny two-body all-hex mesh for the fuzz seed gmsh41.yaml: a punch [0,0.5]^2 x [0,0.5] on a
// block [0,1]^2 x [-0.5,0], 2 x 2 x 2 hexahedra each (cells = 2), quarter model (symmetry planes x = 0,
// y = 0). Two separate boxes, so the bodies share no nodes.
// Regenerate: gmsh -3 -format msh41 punch41.geo -o punch41.msh and
// gmsh -3 -format msh22 -setnumber cells 1 punch41.geo -o punch22.msh (one hexahedron per body)
SetFactory("OpenCASCADE");
Box(1) = {0, 0, -0.5, 1, 1, 0.5};
Box(2) = {0, 0, 0, 0.5, 0.5, 0.5};
If (!Exists(cells)) cells = 2; EndIf  // hexahedra per edge; gmsh -setnumber cells N
Transfinite Curve{:} = cells + 1;
Transfinite Surface{:};
Recombine Surface{:};
Transfinite Volume{:};
// OpenCASCADE numbers a box's faces x-min, x-max, y-min, y-max, z-min, z-max.
Physical Volume("base") = {1};
Physical Volume("punch") = {2};
Physical Surface("base_bottom") = {5};
Physical Surface("base_top") = {6};
Physical Surface("punch_bottom") = {11};
Physical Surface("punch_top") = {12};
Physical Surface("symmetry_x") = {1, 7};
Physical Surface("symmetry_y") = {3, 9};
