// Cantilever beam of 2-node line elements along x, 1 m, 20 elements.
// Physical groups: "beam" (the line), "root" (x = 0), "tip" (x = 1).
Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0};
Line(1) = {1, 2};
Transfinite Curve{1} = 21;
Physical Curve("beam") = {1};
Physical Point("root") = {1};
Physical Point("tip") = {2};
