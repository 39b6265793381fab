// Bad contact input (issue: degenerate shapes, non-positive density, μ < 0, e outside
// [0, 1]): exit code 2, the file and the JSON pointer named, the reason given, from both
// `moreau check` and `moreau run`, and no output left behind.
#include <gtest/gtest.h>

#include <filesystem>

#include "cli_runner.hpp"

namespace fs = std::filesystem;
using namespace moreau_test;

namespace {

std::string scene(int dim, const std::string& contactor, const std::string& law = R"("friction": 0.3)",
                  const std::string& density = "1000") {
  return std::string(R"({"format": "moreau-scene/1", "dimension": )") + std::to_string(dim) +
         R"(, "time": {"step": 0.01, "duration": 0.05}, "materials": {"m": {"density": )" + density +
         R"(}}, "laws": {"l": {"type": "coulomb", )" + law + R"(}},
  "bodies": [{"name": "a", "material": "m", "position": )" + (dim == 2 ? "[0, 0]" : "[0, 0, 0]") +
         R"(, "contactors": [)" + contactor + R"(]}],
  "interactions": [{"groups": ["g", "g"], "law": "l"}], "output": {"file": "out.h5"}})";
}

void expect_bad(const std::string& name, const std::string& text, const std::string& expected) {
  const fs::path dir = scratch_dir(name);
  const fs::path file = write_file(dir, "scene.json", text);
  for (const char* command : {"check", "run"}) {
    Result r = run_moreau({command, file.string()}, dir);
    EXPECT_EQ(r.code, 2) << command << ": " << r.err;
    EXPECT_NE(r.err.find(file.string() + ": "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(expected), std::string::npos) << command << ": expected " << expected << "\ngot:\n" << r.err;
  }
  EXPECT_FALSE(fs::exists(dir / "out.h5"));
  EXPECT_FALSE(fs::exists(dir / "out.h5.frames"));
}

}  // namespace

TEST(ShapeErrors, ZeroRadius) {
  expect_bad("zero_radius", scene(2, R"({"shape": "disk", "radius": 0, "group": "g"})"),
             "at /bodies/0/contactors/0/radius: value 0 out of range");
}

TEST(ShapeErrors, CollinearPolygon) {
  expect_bad("collinear", scene(2, R"({"shape": "polygon", "vertices": [[0, 0], [1, 0], [2, 0]], "group": "g"})"),
             "at /bodies/0/contactors/0/vertices: degenerate polygon: collinear vertices around vertex 1");
}

TEST(ShapeErrors, NonConvexPolygon) {
  expect_bad("nonconvex",
             scene(2, R"({"shape": "polygon", "vertices": [[-1, -1], [1, -1], [0, -0.5], [1, 1], [-1, 1]], "group": "g"})"),
             "at /bodies/0/contactors/0/vertices: degenerate polygon: not convex at vertex");
}

TEST(ShapeErrors, MalformedVertex) {
  expect_bad("vertex", scene(2, R"({"shape": "polygon", "vertices": [[0, 0], [1, 0], [1]], "group": "g"})"),
             "at /bodies/0/contactors/0/vertices/2: expected a vertex [x, y]");
}

TEST(ShapeErrors, ZeroSizeBox) {
  expect_bad("flat_box", scene(3, R"({"shape": "box", "size": [1, 0, 1], "group": "g"})"),
             "at /bodies/0/contactors/0/size: degenerate box: every edge length must be > 0");
}

TEST(ShapeErrors, CoplanarConvex) {
  expect_bad("coplanar",
             scene(3, R"({"shape": "convex", "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0]], "group": "g"})"),
             "at /bodies/0/contactors/0/vertices: degenerate convex shape: the vertices are coplanar");
}

TEST(ShapeErrors, ZeroPlaneNormal) {
  expect_bad("zero_normal",
             std::string(R"({"format": "moreau-scene/1", "dimension": 3, "time": {"step": 0.01, "duration": 0.05},
  "laws": {"l": {"type": "coulomb", "friction": 0.3}},
  "bodies": [{"name": "floor", "fixed": true, "position": [0, 0, 0], "contactors": [{"shape": "plane", "normal": [0, 0, 0], "group": "g"}]},
             {"name": "ball", "mass": 1, "inertia": [1, 1, 1], "position": [0, 0, 1], "contactors": [{"shape": "sphere", "radius": 0.1, "group": "s"}]}],
  "interactions": [{"groups": ["s", "g"], "law": "l"}], "output": {"file": "out.h5"}})"),
             "at /bodies/0/contactors/0/normal: the normal must not be zero");
}

TEST(ShapeErrors, NonPositiveDensity) {
  expect_bad("density", scene(2, R"({"shape": "disk", "radius": 0.1, "group": "g"})", R"("friction": 0.3)", "0"),
             "at /materials/m/density: value 0 out of range");
}

TEST(ShapeErrors, NegativeFriction) {
  expect_bad("friction", scene(2, R"({"shape": "disk", "radius": 0.1, "group": "g"})", R"("friction": -0.1)"),
             "at /laws/l/friction: value -0.1 out of range");
}

TEST(ShapeErrors, RestitutionAboveOne) {
  expect_bad("restitution", scene(2, R"({"shape": "disk", "radius": 0.1, "group": "g"})", R"("friction": 0.3, "restitution": 1.5)"),
             "at /laws/l/restitution: value 1.5 out of range");
}

TEST(ShapeErrors, InitialOverlapDeeperThanTheAlertWarnsWithThePairNamed) {
  const fs::path dir = scratch_dir("overlap");
  const fs::path file = write_file(dir, "scene.json", R"({"format": "moreau-scene/1", "dimension": 2,
  "time": {"step": 0.001, "duration": 0.01}, "materials": {"m": {"density": 1000}},
  "laws": {"l": {"type": "coulomb", "friction": 0.3}}, "detection": {"alert": 0.01},
  "bodies": [{"name": "left", "material": "m", "position": [0, 0], "contactors": [{"shape": "disk", "radius": 0.1, "group": "g"}]},
             {"name": "right", "material": "m", "position": [0.15, 0], "contactors": [{"shape": "disk", "radius": 0.1, "group": "g"}]},
             {"name": "far", "material": "m", "position": [1, 0], "contactors": [{"shape": "disk", "radius": 0.1, "group": "g"}]}],
  "interactions": [{"groups": ["g", "g"], "law": "l"}], "output": {"file": "out.h5"}})");
  Result r = run_moreau({"run", file.string(), "--quiet"}, dir);
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("warning: at the start, bodies \"left\" and \"right\" overlap by 0.05 m (deeper than the alert "
                       "distance 0.01 m)"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(r.err.find("far"), std::string::npos) << r.err;
}

// Contactor placements (clusters): the offset has d numbers, a 3D rotation is a unit
// quaternion, and a 2D `angle` is not a 3D key.
TEST(ShapeErrors, ContactorOffsetOfTheWrongLength) {
  expect_bad("offset_length", scene(2, R"({"shape": "disk", "radius": 0.1, "offset": [0.1, 0, 0], "group": "g"})"),
             "at /bodies/0/contactors/0/offset: expected 2 numbers (dimension 2), got 3");
}

TEST(ShapeErrors, ContactorOrientationNotAUnitQuaternion) {
  expect_bad("placement_quaternion",
             scene(3, R"({"shape": "sphere", "radius": 0.1, "group": "g"},
                        {"shape": "box", "size": [0.1, 0.1, 0.1], "offset": [0.2, 0, 0], "orientation": [1, 1, 0, 0], "group": "g"})"),
             "at /bodies/0/contactors/1/orientation: expected a unit quaternion [w, x, y, z], its norm is 1.414214");
}

TEST(ShapeErrors, ContactorAngleIn3D) {
  expect_bad("placement_angle_3d", scene(3, R"({"shape": "sphere", "radius": 0.1, "angle": 0.5, "group": "g"})"),
             "at /bodies/0/contactors/0/angle: unknown key \"angle\"");
}
