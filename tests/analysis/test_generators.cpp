// Generators (`lattice`, `deposit`): seeded and deterministic, grains without overlap in
// their container and clear of the scene's bodies, sizes from the distribution asked for,
// `moreau generate` writes a plain scene whose run is bit-identical to the original's, and
// what cannot be done is an input error with the JSON pointer (and, for a deposit, how many
// grains it placed).
#include <cmath>
#include <fstream>

#include "analysis_run.hpp"

using namespace moreau_test;
namespace fs = std::filesystem;

namespace {

/// A deposit of disks in a box; `size` a radius or a distribution.
json deposit(int count, const json& size, const json& box, int seed = 1) {
  json d = {{"type", "deposit"}, {"count", count}, {"seed", seed},
            {"container", {{"box", {{"min", box[0]}, {"max", box[1]}}}}},
            {"grain", {{"shape", "disk"}, {"group", "grain"}}}, {"body", {{"material", "m"}}}};
  d[size.is_number() ? "radius" : "size"] = size;
  return d;
}

/// `moreau generate`: the expanded scene, or the failed run's result.
json generate(const std::string& name, const json& scene, Result* failed = nullptr) {
  const auto dir = scratch_dir(name);
  const auto in = write_file(dir, "scene.json", scene.dump(1));
  Result r = run_moreau({"generate", in.string(), "--out", "full.json"}, dir);
  if (failed) {
    *failed = r;
    return {};
  }
  EXPECT_EQ(r.code, 0) << r.err;
  std::ifstream f(dir / "full.json");
  return json::parse(f);
}

/// Grains (bodies with one disk or sphere) as centre and radius.
struct Ball {
  std::vector<double> x;
  double r;
};
std::vector<Ball> balls(const json& scene) {
  std::vector<Ball> out;
  for (const auto& b : scene["bodies"]) {
    const auto& c = b["contactors"][0];
    if (c["shape"] == "disk" || c["shape"] == "sphere") out.push_back({b["position"].get<std::vector<double>>(), c["radius"]});
  }
  return out;
}

double overlap(const std::vector<Ball>& g) {
  double worst = 0;
  for (std::size_t i = 0; i < g.size(); ++i)
    for (std::size_t j = i + 1; j < g.size(); ++j) {
      double s = 0;
      for (std::size_t k = 0; k < g[i].x.size(); ++k) s += (g[i].x[k] - g[j].x[k]) * (g[i].x[k] - g[j].x[k]);
      worst = std::max(worst, g[i].r + g[j].r - std::sqrt(s));
    }
  return worst;
}

void expect_bad(const std::string& name, const json& scene, const std::string& where, const std::string& what) {
  Result r;
  generate(name, scene, &r);
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("at " + where + ": "), std::string::npos) << "expected the pointer " << where << ":\n" << r.err;
  EXPECT_NE(r.err.find(what), std::string::npos) << "expected: " << what << "\n" << r.err;
  // `run` and `check` say the same, and leave nothing.
  const auto dir = scratch_dir(name + "_run");
  expect_input_error(dir, write_file(dir, "scene.json", scene.dump(1)), where, what);
}

}  // namespace

TEST(Generators, DepositIsSeededDeterministicAndWithoutOverlap) {
  json s = floor_scene_2d();
  s["generators"] = {deposit(300, {{"distribution", "uniform"}, {"min", 0.002}, {"max", 0.003}}, {{-0.1, 0.0}, {0.1, 0.3}}, 7)};
  const json a = generate("deposit_a", s), b = generate("deposit_b", s);
  EXPECT_EQ(a.dump(), b.dump()) << "same seed, same bodies";
  s["generators"][0]["seed"] = 8;
  const json c = generate("deposit_c", s);
  EXPECT_NE(a.dump(), c.dump()) << "another seed, other bodies";
  EXPECT_FALSE(a.contains("generators"));
  ASSERT_EQ(a["bodies"].size(), 301u);
  EXPECT_EQ(a["bodies"][1]["name"], "grain_0");
  const auto g = balls(a);
  ASSERT_EQ(g.size(), 300u);
  EXPECT_LE(overlap(g), 0.0);
  for (const auto& x : g) {
    EXPECT_GE(x.r, 0.002);
    EXPECT_LE(x.r, 0.003);
    EXPECT_GE(x.x[0] - x.r, -0.1);
    EXPECT_LE(x.x[0] + x.r, 0.1);
    EXPECT_GE(x.x[1] - x.r, 0.0) << "clear of the floor (its top is at y = 0)";
    EXPECT_LE(x.x[1] + x.r, 0.3);
  }
}

TEST(Generators, SizeDistributions) {
  json s = floor_scene_2d();
  s["generators"] = {deposit(200, {{"distribution", "list"}, {"values", {0.002, 0.004}}, {"fractions", {0.75, 0.25}}},
                             {{-0.1, 0.0}, {0.1, 0.4}}),
                     deposit(400, {{"distribution", "lognormal"}, {"median", 0.002}, {"sigma", 0.2}, {"min", 0.0015}, {"max", 0.003}},
                             {{-0.1, 0.4}, {0.1, 0.8}})};
  s["generators"][1]["name"] = "fine";
  const json a = generate("sizes", s);
  int small = 0, large = 0;
  std::vector<double> logn;
  for (const auto& b : a["bodies"]) {
    if (!b.contains("contactors") || b["contactors"][0]["shape"] != "disk") continue;
    const double r = b["contactors"][0]["radius"];
    if (b["name"].get<std::string>().rfind("grain_", 0) == 0) (r == 0.002 ? small : large) += 1;
    else logn.push_back(r);
  }
  EXPECT_EQ(small, 150) << "fractions of the number, exactly";
  EXPECT_EQ(large, 50);
  ASSERT_EQ(logn.size(), 400u);
  std::sort(logn.begin(), logn.end());
  EXPECT_GE(logn.front(), 0.0015);
  EXPECT_LE(logn.back(), 0.003);
  EXPECT_NEAR(logn[200], 0.002, 0.0001) << "median";
  EXPECT_LE(overlap(balls(a)), 0.0) << "the second deposit keeps clear of the first";
}

TEST(Generators, PolygonsConvexAndACylinder) {
  json s = floor_scene_2d();
  json d = deposit(40, 0.004, {{-0.1, 0.0}, {0.1, 0.2}});
  d["grain"] = {{"shape", "polygon"}, {"sides", 5}, {"group", "grain"}};
  s["generators"] = {d};
  const json a = generate("polygons", s);
  ASSERT_EQ(a["bodies"].size(), 41u);
  const auto& v = a["bodies"][1]["contactors"][0]["vertices"];
  ASSERT_EQ(v.size(), 5u);
  for (const auto& p : v) EXPECT_NEAR(std::hypot(p[0].get<double>(), p[1].get<double>()), 0.004, 1e-15);
  Result r = run_moreau({"check", write_file(scratch_dir("polygons_check"), "s.json", a.dump()).string()});
  EXPECT_EQ(r.code, 0) << r.err;

  json s3 = json::parse(R"({"format": "moreau-scene/1", "dimension": 3, "time": {"step": 1e-3, "duration": 0.002},
    "gravity": [0, 0, -9.81], "materials": {"m": {"density": 1000}}, "laws": {"l": {"type": "coulomb", "friction": 0.3}},
    "bodies": [{"name": "floor", "fixed": true, "position": [0, 0, 0], "contactors": [{"shape": "plane", "group": "wall"}]}],
    "interactions": [{"groups": ["rock", "rock"], "law": "l"}, {"groups": ["rock", "wall"], "law": "l"}],
    "generators": [{"type": "deposit", "count": 60, "radius": 0.01, "grain": {"shape": "convex", "corners": 10, "group": "rock"},
                    "container": {"cylinder": {"center": [0, 0, 0], "radius": 0.06, "height": 0.15}}, "body": {"material": "m"}}],
    "output": {"every": 1}})");
  const json b = generate("convex", s3);
  ASSERT_EQ(b["bodies"].size(), 61u);
  std::vector<Ball> g;
  for (std::size_t i = 1; i < b["bodies"].size(); ++i) {
    const auto x = b["bodies"][i]["position"].get<std::vector<double>>();
    EXPECT_LE(std::hypot(x[0], x[1]) + 0.01, 0.06 + 1e-15) << "inside the cylinder";
    EXPECT_GE(x[2], 0.01);
    EXPECT_LE(x[2], 0.14);
    EXPECT_EQ(b["bodies"][i]["contactors"][0]["vertices"].size(), 10u);
    g.push_back({x, 0.01});
  }
  EXPECT_LE(overlap(g), 0.0) << "bounding spheres apart";
  Result run = run_moreau({"run", write_file(scratch_dir("convex_run"), "s.json", b.dump()).string(), "--quiet"},
                          scratch_dir("convex_run2"));
  EXPECT_EQ(run.code, 0) << run.err;
}

TEST(Generators, LatticesAndAvoid) {
  json s = floor_scene_2d();
  s["generators"] = {{{"type", "lattice"}, {"lattice", "triangular"}, {"counts", {5, 4}}, {"short_rows", true},
                      {"fixed_rows", 1}, {"origin", {-0.04, 0.01}}, {"radius", 0.01},
                      {"grain", {{"shape", "disk"}, {"group", "grain"}}}, {"body", {{"material", "m"}}}}};
  const json a = generate("triangular", s);
  ASSERT_EQ(a["bodies"].size(), 1u + 5 + 4 + 5 + 4);
  EXPECT_EQ(a["bodies"][1].value("fixed", false), true);
  EXPECT_FALSE(a["bodies"][6].contains("fixed"));
  const auto x5 = a["bodies"][6]["position"].get<std::vector<double>>();  // first of the second row
  EXPECT_NEAR(x5[0], -0.03, 1e-15);
  EXPECT_NEAR(x5[1], 0.01 + 0.02 * std::sqrt(3.0) / 2, 1e-15);
  EXPECT_NEAR(overlap(balls(a)), 0.0, 1e-15) << "touching, not overlapping";

  json s3 = json::parse(R"({"format": "moreau-scene/1", "dimension": 3, "time": {"step": 1e-3, "duration": 0.002},
    "materials": {"m": {"density": 1000}}, "bodies": [],
    "generators": [{"type": "lattice", "lattice": "hcp", "counts": [3, 3, 3], "origin": [0, 0, 0], "radius": 0.5,
                    "grain": {"shape": "sphere"}, "body": {"material": "m"}},
                   {"type": "lattice", "lattice": "fcc", "counts": [3, 3, 2], "origin": [10, 0, 0], "radius": 0.5, "short_rows": true,
                    "grain": {"shape": "sphere"}, "body": {"material": "m"}, "name": "f"}]})");
  const json b = generate("lattices3d", s3);
  ASSERT_EQ(b["bodies"].size(), 27u + 9 + 4);
  EXPECT_NEAR(overlap(balls(b)), 0.0, 1e-14) << "close packed: touching";
  // hcp: a B layer over the hollows at height √(2/3)·s.
  const auto z1 = b["bodies"][9]["position"].get<std::vector<double>>();
  EXPECT_NEAR(z1[2], std::sqrt(2.0 / 3.0), 1e-15);

  // A deposit between two walls keeps clear of them.
  json w = floor_scene_2d();
  w["bodies"].push_back({{"name", "left"}, {"fixed", true}, {"position", {-0.02, 0.1}}, {"angle", M_PI / 2},
                         {"contactors", {{{"shape", "segment"}, {"length", 0.2}, {"thickness", 0.01}, {"group", "wall"}}}}});
  w["generators"] = {deposit(50, 0.003, {{-0.05, 0.0}, {0.05, 0.2}})};
  const json c = generate("avoid", w);
  for (const auto& g : balls(c)) EXPECT_GE(std::fabs(g.x[0] - (-0.02)), 0.005 + g.r - 1e-15) << "clear of the wall";
}

TEST(Generators, GenerateWritesAReproducibleScene) {
  json s = floor_scene_2d();
  s["time"]["duration"] = 0.05;
  s["generators"] = {deposit(80, {{"distribution", "uniform"}, {"min", 0.003}, {"max", 0.004}}, {{-0.1, 0.0}, {0.1, 0.1}})};
  SceneRun original = run_json("reproducible_a", s);
  const json full = generate("reproducible_full", s);
  SceneRun plain = run_json("reproducible_b", full);
  ASSERT_FALSE(original.frames.empty());
  ASSERT_EQ(original.frames, plain.frames);
  for (const char* f : {"position", "velocity", "angle", "contacts/impulse"})
    EXPECT_EQ(original.at(original.last(), f), plain.at(plain.last(), f)) << f << ": bit-identical";
}

TEST(Generators, DepositThatDoesNotFitSaysHowManyItPlaced) {
  json s = floor_scene_2d();
  s["generators"] = {deposit(500, 0.005, {{-0.05, 0.0}, {0.05, 0.1}})};
  s["generators"][0]["attempts"] = 200;
  Result r;
  generate("too_many", s, &r);
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("at /generators/0/count: placed "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(" of 500 grains without overlap"), std::string::npos) << r.err;
  expect_bad("too_many_run", s, "/generators/0/count", "of 500 grains without overlap");
}

TEST(Generators, BadInput) {
  json s = floor_scene_2d();
  s["generators"] = {{{"type", "lattise"}}};
  expect_bad("unknown_type", s, "/generators/0/type", "lattice");
  s["generators"] = {deposit(10, 0.003, {{-0.05, 0.0}, {0.05, 0.1}})};
  s["generators"][0]["grain"]["shape"] = "sphere";
  expect_bad("wrong_dim", s, "/generators/0/grain/shape", "does not exist in 2D scenes");
  s["generators"] = {{{"type", "lattice"}, {"lattice", "square"}, {"counts", {3, 3}}, {"origin", {0, 0.1}}, {"radius", 0.01},
                      {"spacing", 0.015}, {"grain", {{"shape", "disk"}}}, {"body", {{"material", "m"}}}}};
  expect_bad("overlapping_lattice", s, "/generators/0", "grains overlap");
  s["generators"][0]["spacing"] = 0.02;
  s["generators"][0]["body"]["material"] = "unobtainium";
  expect_bad("generated_material", s, "/bodies/1/material", "(body 0 made by /generators/0)");
  s["generators"][0]["body"]["material"] = "m";
  s["generators"][0]["name"] = "floor";
  s["bodies"][0]["name"] = "floor_3";
  expect_bad("name_clash", s, "/generators/0/name", "already has a body named \"floor_3\"");
  s["bodies"][0]["name"] = "floor";
  s["generators"][0]["avoid"] = {"nowhere"};
  expect_bad("avoid_unknown", s, "/generators/0/avoid/0", "no body named \"nowhere\"");
  s["generators"][0].erase("avoid");
  s["generators"][0]["wobble"] = 1;
  expect_bad("unknown_key", s, "/generators/0/wobble", "unknown key");
}
