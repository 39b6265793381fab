// A surface bounded by a clockwise loop: Gmsh meshes it with normal -z (clockwise elements).
SetFactory("Built-in");
h = 0.5;
Point(1) = {0, 0, 0, h}; Point(2) = {2, 0, 0, h}; Point(3) = {2, 1, 0, h}; Point(4) = {0, 1, 0, h};
Line(1) = {1, 4}; Line(2) = {4, 3}; Line(3) = {3, 2}; Line(4) = {2, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Physical Surface("body") = {1};
Physical Curve("left") = {1};
