// 1 x 1 x 2 box of tetrahedra; physical faces, volume and a corner point.
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 1, 1, 2};
Mesh.MeshSizeMax = 0.4;
Physical Surface("bottom") = {5};
Physical Surface("top") = {6};
Physical Volume("solid") = {1};
Physical Point("corner") = {1};
