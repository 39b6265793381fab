// A disk of radius 0.1 m centred at (0, 0.1), meshed finer near its lowest point (0, 0)
// where it touches a plane (Hertz validation, tests/validation/test_elastic.cpp): size sc
// within 0.03 m of that point, growing to 0.01 m. sc is set on the command line:
//   gmsh hertz_disk.geo -2 -setnumber sc 0.001 -format msh41 -o hertz_disk_1.msh
If (!Exists(sc))
  sc = 0.001;
EndIf
R = 0.1;
Point(1) = {0, R, 0};
Point(2) = {0, 0, 0};
Point(3) = {R, R, 0};
Point(4) = {0, 2 * R, 0};
Point(5) = {-R, R, 0};
Circle(1) = {2, 1, 3};
Circle(2) = {3, 1, 4};
Circle(3) = {4, 1, 5};
Circle(4) = {5, 1, 2};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Physical Curve("boundary") = {1, 2, 3, 4};
Physical Surface("disk") = {1};
Field[1] = Distance;
Field[1].PointsList = {2};
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = sc;
Field[2].SizeMax = 0.01;
Field[2].DistMin = 0.03;
Field[2].DistMax = 0.08;
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
