// A 0.3 x 0.1 x 0.05 m box of 10-node tetrahedra for AbaqusReader.GmshDeckThroughInclude.
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 0.3, 0.1, 0.05};
Physical Volume("PART") = {1};
Mesh.CharacteristicLengthMin = 0.1;
Mesh.CharacteristicLengthMax = 0.1;
Mesh.ElementOrder = 2;
