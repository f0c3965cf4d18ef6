// A triangulated plate 0.2 x 0.1 m (3-node shells) with a stiffener of
// line elements along y = 0, and a tetrahedral (4-node) block beside it.
// Physical groups: "plate" (triangles), "stiffener" (lines, also in the
// group "edges" with the plate's edge x = 0), "block" (tetrahedra).
SetFactory("OpenCASCADE");
Rectangle(1) = {0, 0, 0, 0.2, 0.1};
Box(2) = {0.5, 0, 0, 0.1, 0.1, 0.1};
Mesh.MeshSizeMin = 0.05;
Mesh.MeshSizeMax = 0.05;
Physical Surface("plate") = {1};
Physical Curve("stiffener") = {1};
Physical Curve("edges") = {1, 4};
Physical Volume("block") = {2};
