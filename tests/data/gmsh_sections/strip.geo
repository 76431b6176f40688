// The plane version of bar.geo (two fragmented rectangles): tests/cli/gmsh_sections.sh.
SetFactory("OpenCASCADE");
Rectangle(1) = {0, 0, 0, 1, 0.5};
Rectangle(2) = {1, 0, 0, 1, 0.5};
BooleanFragments{ Surface{1}; Delete; }{ Surface{2}; Delete; }
Transfinite Curve{:} = 3;
Transfinite Surface{:};
Recombine Surface{:};
e = 1e-6;
Physical Surface("steel_half") = Surface In BoundingBox{-e, -e, -e, 1 + e, 0.5 + e, e};
Physical Surface("aluminium_half") = Surface In BoundingBox{1 - e, -e, -e, 2 + e, 0.5 + e, e};
Physical Curve("fixed") = Curve In BoundingBox{-e, -e, -e, e, 0.5 + e, e};
Physical Curve("ymin") = Curve In BoundingBox{-e, -e, -e, 2 + e, e, e};
Physical Curve("end") = Curve In BoundingBox{2 - e, -e, -e, 2 + e, 0.5 + e, e};
