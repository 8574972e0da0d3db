// A unit cube: clamped at z = 0, loaded at z = 1; 10-node tetrahedra.
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 1, 1, 1};
Mesh.MeshSizeMin = 1;
Mesh.MeshSizeMax = 1;
Physical Surface("clamped") = {5};
Physical Surface("loaded") = {6};
Physical Volume("solid") = {1};
