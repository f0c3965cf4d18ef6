// Block 0.3 x 0.2 x 0.1 m of 8-node hexahedra (3 x 2 x 1), by extrusion.
// Physical groups: "block" (the volume), "bottom" (face z = 0), and the
// face x = 0 as an unnamed group 7 (read as "group7").
Point(1) = {0, 0, 0}; Point(2) = {0.3, 0, 0}; Point(3) = {0.3, 0.2, 0}; Point(4) = {0, 0.2, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 3} = 4; Transfinite Curve{2, 4} = 3;
Transfinite Surface{1}; Recombine Surface{1};
out[] = Extrude {0, 0, 0.1} { Surface{1}; Layers{1}; Recombine; };
Physical Volume("block") = {out[1]};
Physical Surface("bottom") = {1};
Physical Surface(7) = {out[5]};
