// A sphere of radius 0.1 m centred at (0, 0, 0.1), meshed finer near its lowest point
// (0, 0, 0) where it touches a plane (3D Hertz validation, tests/validation/test_hertz_sphere.cpp):
// size sc within 0.012 m of that point, then growing by half the extra distance, up to
// 0.025 m. sc is set on the
// command line:
//   gmsh hertz_sphere.geo -3 -setnumber sc 0.002 -format msh41 -bin -o hertz_sphere_2.msh
SetFactory("OpenCASCADE");
If (!Exists(sc))
  sc = 0.001;
EndIf
R = 0.1;
Sphere(1) = {0, 0, R, R};
// OpenCASCADE's sphere has its poles on the z axis; turn them to ±y so that the contact
// point is an ordinary point of the surface (no pole, no seam).
Rotate {{1, 0, 0}, {0, 0, R}, Pi / 2} { Volume{1}; }
Physical Surface("boundary") = {1};
Physical Volume("sphere") = {1};
Field[1] = MathEval;
Field[1].F = Sprintf("Min(0.025, Max(%g, %g + (Sqrt(x*x + y*y + z*z) - 0.012) * 0.5))", sc, sc);
Background Field = 1;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
