// Bad `analyses`: exit 2, the JSON pointer and why, from `run` and `check` alike, and no
// output left behind.
#include <filesystem>

#include "analysis_run.hpp"

using namespace moreau_test;
namespace fs = std::filesystem;

namespace {

/// A floor and a ball.
json scene() {
  json s = floor_scene_2d();
  s["bodies"].push_back(json::parse(R"({"name": "ball", "material": "m", "position": [0, 0.05],
    "contactors": [{"shape": "disk", "radius": 0.01, "group": "grain"}]})"));
  s["output"]["file"] = "out.h5";  // expect_input_error checks that none is left behind
  return s;
}

void expect_bad(const std::string& name, const json& analyses, const std::string& where, const std::string& what) {
  json s = scene();
  s["analyses"] = analyses;
  const fs::path dir = scratch_dir(name);
  expect_input_error(dir, write_file(dir, "scene.json", s.dump(1)), where, what);
}

}  // namespace

TEST(AnalysisErrors, RegionOutsideTheScene) {
  expect_bad("outside", {{{"type", "stress"}, {"region", {{"min", {5, 5}}, {"max", {6, 6}}}}}}, "/analyses/0/region",
             "lies outside the scene, whose bodies and shapes span [-0.11, -0.02] to [0.11, 0.06]");
}

TEST(AnalysisErrors, EmptyOrMalformedRegion) {
  expect_bad("empty_box", {{{"type", "fabric"}, {"region", {{"min", {0, 0}}, {"max", {0.1, -0.1}}}}}}, "/analyses/0/region/max/1",
             "the box is empty");
  expect_bad("region_word", {{{"type", "fabric"}, {"region", "everything"}}}, "/analyses/0/region", "expected \"all\"");
  expect_bad("region_dim", {{{"type", "fabric"}, {"region", {{"min", {0, 0, 0}}, {"max", {1, 1}}}}}}, "/analyses/0/region/min",
             "expected 2 numbers");
}

TEST(AnalysisErrors, UnknownBodiesAndGroups) {
  expect_bad("unknown_body", {{{"type", "walls"}, {"bodies", {"floor", "roof"}}}}, "/analyses/0/bodies/1", "no body named \"roof\"");
  expect_bad("unknown_group", {{{"type", "polarization"}, {"pairs", json::array({json::array({"grain", "glass"})})}}}, "/analyses/0/pairs/0/1",
             "no contactor has group \"glass\" (groups: wall, grain)");
}

TEST(AnalysisErrors, NamesTypesAndKeys) {
  expect_bad("duplicate", {{{"type", "fabric"}}, {{"type", "fabric"}}}, "/analyses/1", "two analyses named \"fabric\"");
  expect_bad("unknown_type", {{{"type", "strain"}}}, "/analyses/0/type", "stress");
  expect_bad("unknown_key", {{{"type", "stress"}, {"orign", {0, 0}}}}, "/analyses/0/orign", "did you mean \"origin\"");
  expect_bad("every", {{{"type", "stress"}, {"every", 0}}}, "/analyses/0/every", "expected an integer >= 1");
  expect_bad("energy_box", {{{"type", "energy"}, {"region", {{"min", {0, 0}}, {"max", {0.1, 0.1}}}}}}, "/analyses/0/region",
             "the energy balance is for the whole sample");
  expect_bad("profile_axis", {{{"type", "stress"}, {"profile", {{"axis", "z"}}}}}, "/analyses/0/profile/axis",
             "expected an axis");
}
