// Block 0.4 x 0.2 x 0.1 m of 10-node (second-order) tetrahedra.
// Physical groups: "block" (the volume), "base" (face z = 0).
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 0.4, 0.2, 0.1};
Mesh.MeshSizeMin = 0.1;
Mesh.MeshSizeMax = 0.2;
Mesh.ElementOrder = 2;
Physical Volume("block") = {1};
Physical Surface("base") = {5};
