// A bar of two halves meshed as one connected mesh (the volumes fragmented: the halves share
// the nodes of x = 1), each half a physical volume: tests/cli/gmsh_sections.sh.
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 1, 0.5, 0.5};
Box(2) = {1, 0, 0, 1, 0.5, 0.5};
BooleanFragments{ Volume{1}; Delete; }{ Volume{2}; Delete; }
Transfinite Curve{:} = 3;
Transfinite Surface{:};
Recombine Surface{:};
Transfinite Volume{:};
e = 1e-6;
Physical Volume("steel_half") = Volume In BoundingBox{-e, -e, -e, 1 + e, 0.5 + e, 0.5 + e};
Physical Volume("aluminium_half") = Volume In BoundingBox{1 - e, -e, -e, 2 + e, 0.5 + e, 0.5 + e};
Physical Surface("fixed") = Surface In BoundingBox{-e, -e, -e, e, 0.5 + e, 0.5 + e};
Physical Surface("ymin") = Surface In BoundingBox{-e, -e, -e, 2 + e, e, 0.5 + e};
Physical Surface("zmin") = Surface In BoundingBox{-e, -e, -e, 2 + e, 0.5 + e, e};
Physical Surface("end") = Surface In BoundingBox{2 - e, -e, -e, 2 + e, 0.5 + e, 0.5 + e};
