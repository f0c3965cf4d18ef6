// Cantilever strip of 4-node shells: 1 m x 0.05 m, 40 x 2 quads.
// Physical groups: "strip" (the surface), "clamp" (edge x = 0, line
// elements), "tip" (the corner point at x = 1, y = 0).
L = 1.0; b = 0.05;
Point(1) = {0, 0, 0}; Point(2) = {L, 0, 0}; Point(3) = {L, b, 0}; Point(4) = {0, b, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 3} = 41; Transfinite Curve{2, 4} = 3;
Transfinite Surface{1}; Recombine Surface{1};
Physical Surface("strip") = {1};
Physical Curve("clamp") = {4};
Physical Point("tip") = {2};
