// Block 0.4 x 0.2 x 0.1 m of 10-node tetrahedra, exported by gmsh as legacy
// VTK (cell type 24) to check the quadratic tetrahedron's node order. Only
// the volume is a physical group, so the file has tetrahedra only.
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 0.4, 0.2, 0.1};
Mesh.MeshSizeMin = 0.1;
Mesh.MeshSizeMax = 0.2;
Mesh.ElementOrder = 2;
Physical Volume("block") = {1};
