// Tiny two-body tet10 mesh for the fuzz seed gmsh_tet10.yaml (and, exported, the deck seed
// punch_tet10.inp): the punch on a block of punch41.geo, meshed with 10-node tetrahedra
// (unstructured, element size 0.5). Regenerate:
//   gmsh -3 -format msh41 punch_tet10.geo -o punch_tet10.msh
//   build/feticon export gmsh_tet10.yaml --format calculix --output /tmp/x && cp /tmp/x/feticon.inp punch_tet10.inp
SetFactory("OpenCASCADE");
Box(1) = {0, 0, -0.5, 1, 1, 0.5};
Box(2) = {0, 0, 0, 0.5, 0.5, 0.5};
Mesh.MeshSizeMax = 0.5;
Mesh.ElementOrder = 2;
// OpenCASCADE numbers a box's faces x-min, x-max, y-min, y-max, z-min, z-max.
Physical Volume("base") = {1};
Physical Volume("punch") = {2};
Physical Surface("base_bottom") = {5};
Physical Surface("base_top") = {6};
Physical Surface("punch_bottom") = {11};
Physical Surface("punch_top") = {12};
Physical Surface("symmetry_x") = {1, 7};
Physical Surface("symmetry_y") = {3, 9};
