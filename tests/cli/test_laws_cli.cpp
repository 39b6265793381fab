// Contact laws through `moreau` (docs/laws.md): bad parameters exit 2 with the JSON
// pointer and what is expected; the laws' internal variables are in the frames, with the
// bond counts, drawn in the viewer description, and restored on restart bit-identically.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

#include "cli_runner.hpp"
#include "h5_read.hpp"

namespace fs = std::filesystem;
using namespace moreau_test;

namespace {

/// Two 2D blocks glued by `law` (JSON), the top one pulled up by a force growing with
/// time, gravity down: the glue holds, damages or breaks. `extra`: more top-level keys.
std::string glued_blocks(const std::string& law, const std::string& extra = "", double duration = 0.3) {
  std::ostringstream s;
  s << R"({"format": "moreau-scene/1", "dimension": 2, "time": {"step": 1e-3, "duration": )" << duration << R"(},
  "gravity": [0, -9.81], "materials": {"m": {"density": 1000}},
  "laws": {"glue": )" << law << R"(},
  "interactions": [{"groups": ["top", "bottom"], "law": "glue"}],
  "forces": [{"type": "constant", "body": "top", "rate": [200, 4000]}], )" << extra << R"(
  "output": {"file": "out.h5", "every": 25},
  "bodies": [{"name": "bottom", "fixed": true, "position": [0, -0.05], "contactors": [{"shape": "polygon", "vertices": [[-0.1, -0.05], [0.1, -0.05], [0.1, 0.05], [-0.1, 0.05]], "group": "bottom"}]},
    {"name": "top", "material": "m", "position": [0, 0.05], "contactors": [{"shape": "polygon", "vertices": [[-0.1, -0.05], [0.1, -0.05], [0.1, 0.05], [-0.1, 0.05]], "group": "top"}]}]})";
  return s.str();
}

const char* czm = R"({"type": "czm", "normal_stiffness": 1e7, "tangential_stiffness": 1e7, "normal_strength": 2000,
  "shear_strength": 2000, "mode_I_energy": 2, "mode_II_energy": 2, "area": 0.1, "friction": 0.5})";
const char* cohesive = R"({"type": "cohesive", "tensile_strength": 2000, "cohesion": 1500, "friction": 0.5, "area": 0.1})";

void expect_bad(const std::string& name, const std::string& scene_text, const std::string& expected) {
  const fs::path dir = scratch_dir(name);
  const fs::path scene = write_file(dir, "scene.json", scene_text);
  Result r = run_moreau({"run", scene.string()}, dir);
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find(expected), std::string::npos) << "expected: " << expected << "\ngot:\n" << r.err;
  EXPECT_FALSE(fs::exists(dir / "out.h5")) << "bad input must leave no output";
}

std::string with(std::string law, const std::string& from, const std::string& to) {
  const auto p = law.find(from);
  if (p == std::string::npos) throw std::logic_error("no " + from);
  return law.replace(p, from.size(), to);
}

std::string slurp(const fs::path& p) {
  std::ifstream f(p);
  return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
}

}  // namespace

TEST(LawsCli, NegativeStrengthStiffnessOrEnergyIsRefusedWithItsPointer) {
  expect_bad("czm_strength", glued_blocks(with(czm, "\"normal_strength\": 2000", "\"normal_strength\": -1")),
             "at /laws/glue/normal_strength: value -1 out of range: expected > 0");
  expect_bad("czm_stiffness", glued_blocks(with(czm, "\"tangential_stiffness\": 1e7", "\"tangential_stiffness\": 0")),
             "at /laws/glue/tangential_stiffness: value 0 out of range: expected > 0");
  expect_bad("czm_energy", glued_blocks(with(czm, "\"mode_II_energy\": 2", "\"mode_II_energy\": -2")),
             "at /laws/glue/mode_II_energy: value -2 out of range: expected > 0");
  expect_bad("cohesive_strength", glued_blocks(with(cohesive, "\"tensile_strength\": 2000", "\"tensile_strength\": -5")),
             "at /laws/glue/tensile_strength: value -5 out of range: expected > 0");
  expect_bad("elastic_stiffness", glued_blocks(R"({"type": "elastic", "stiffness": -1e6})"),
             "at /laws/glue/stiffness: value -1e+06 out of range: expected > 0");
  expect_bad("wet_adhesion", glued_blocks(R"({"type": "wet", "adhesion": -1, "rupture_distance": 1e-4})"),
             "at /laws/glue/adhesion: value -1 out of range: expected > 0");
}

TEST(LawsCli, ParametersOutOfTheirRangeAreRefusedWithWhatIsExpected) {
  expect_bad("static_below_dynamic", glued_blocks(R"({"type": "coulomb", "friction": 0.5, "static_friction": 0.3})"),
             "at /laws/glue/static_friction: expected a static friction coefficient at least the (dynamic) friction 0.5, got 0.3");
  expect_bad("tension_beyond_apex", glued_blocks(with(cohesive, "\"tensile_strength\": 2000", "\"tensile_strength\": 4000")),
             "at /laws/glue/tensile_strength: expected at most cohesion / static friction = 3000 Pa (the apex of the "
             "Mohr-Coulomb envelope), got 4000");
  expect_bad("cohesion_without_friction", glued_blocks(with(cohesive, "\"friction\": 0.5", "\"friction\": 0")),
             "at /laws/glue/friction: value 0 out of range: expected > 0");
  expect_bad("snap_back", glued_blocks(with(czm, "\"mode_I_energy\": 2", "\"mode_I_energy\": 0.1")),
             "at /laws/glue/mode_I_energy: expected at least normal_strength^2 / (2 normal_stiffness) = 0.2 J/m2 (the "
             "elastic energy at the strength), got 0.1");
  expect_bad("meniscus_beyond_alert",
             glued_blocks(R"({"type": "wet", "adhesion": 1, "rupture_distance": 1e-3})", R"("detection": {"alert": 1e-4},)"),
             "at /detection/alert: law \"glue\" acts on contacts up to 0.001 m apart: expected an alert distance of at least "
             "that (it is 0.0001 m)");
  expect_bad("czm_beyond_alert", glued_blocks(czm),
             "at /detection/alert: law \"glue\" acts on contacts up to 0.002 m apart");
}

TEST(LawsCli, BondsAndDamageAreInTheFramesCountedAndDrawn) {
  const fs::path dir = scratch_dir("laws_frames");
  const fs::path scene = write_file(dir, "scene.json", glued_blocks(czm, R"("detection": {"alert": 3e-3},)"));
  Result r = run_moreau({"run", scene.string(), "--quiet"}, dir);
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string out = (dir / "out.h5").string();
  const auto frames = frame_names(out);
  double last_damage = 0;
  bool broke = false;
  for (std::size_t f = 1; f < frames.size(); ++f) {
    const auto damage = read_doubles(out, "/frames/" + frames[f] + "/contacts/damage");
    const auto bond = read_doubles(out, "/frames/" + frames[f] + "/contacts/bond");
    const auto opening = read_doubles(out, "/frames/" + frames[f] + "/contacts/opening");
    const auto bonds = read_doubles(out, "/frames/" + frames[f] + "/laws/bonds");
    const auto broken = read_doubles(out, "/frames/" + frames[f] + "/laws/broken");
    ASSERT_EQ(bonds.size(), 1u);
    ASSERT_EQ(opening.size(), 2 * bond.size());
    double intact = 0;
    for (std::size_t c = 0; c < bond.size(); ++c) {
      intact += bond[c] == 1;
      EXPECT_GE(damage[c], last_damage - 1) << "damage is a fraction";
    }
    EXPECT_EQ(bonds[0], intact);
    if (!damage.empty()) last_damage = damage[0];
    broke = broke || broken[0] == 2;
  }
  EXPECT_TRUE(broke) << "the pulled block's two bonds break within the run";
  const std::string xmf = slurp(dir / "out.xmf");
  for (const char* name : {"Attribute Name=\"bond\"", "Attribute Name=\"damage\"", "Attribute Name=\"opening\""})
    EXPECT_NE(xmf.find(name), std::string::npos) << name << " in the viewer description";
}

TEST(LawsCli, RestartRestoresTheLawsVariablesBitIdentically) {
  // The block is pulled through damage to rupture; the restart point (step 150) falls while
  // the bonds are damaged and intact.
  const fs::path dir = scratch_dir("laws_restart");
  const std::string text = glued_blocks(czm, R"("detection": {"alert": 3e-3},)");
  const fs::path scene = write_file(dir, "scene.json", text);
  ASSERT_EQ(run_moreau({"run", scene.string(), "--out", "full.h5", "--quiet"}, dir).code, 0);
  ASSERT_EQ(run_moreau({"run", scene.string(), "--out", "part.h5", "--steps", "150", "--quiet"}, dir).code, 0);
  const auto mid = read_doubles((dir / "part.h5").string(), "/frames/00000150/contacts/damage");
  ASSERT_FALSE(mid.empty());
  const double most = *std::max_element(mid.begin(), mid.end());
  EXPECT_GT(most, 0) << "the restart point should fall while a bond is damaged";
  EXPECT_LT(most, 1);
  Result r = run_moreau({"run", scene.string(), "--restart", "part.h5", "--out", "rest.h5", "--quiet"}, dir);
  ASSERT_EQ(r.code, 0) << r.err;
  for (const char* field : {"position", "velocity", "contacts/impulse", "contacts/damage", "contacts/bond", "contacts/opening",
                            "laws/broken"}) {
    for (const char* frame : {"00000200", "00000300"}) {
      const auto a = read_doubles((dir / "full.h5").string(), std::string("/frames/") + frame + "/" + field);
      const auto b = read_doubles((dir / "rest.h5").string(), std::string("/frames/") + frame + "/" + field);
      ASSERT_EQ(a.size(), b.size()) << field;
      for (std::size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a[i], b[i]) << field << "[" << i << "] at " << frame;
    }
  }
  // A run whose laws kept other variables cannot be continued by this scene.
  const std::string plain = glued_blocks(R"({"type": "coulomb", "friction": 0.5})");
  const fs::path plain_scene = write_file(dir, "plain.json", plain);
  ASSERT_EQ(run_moreau({"run", plain_scene.string(), "--out", "plain.h5", "--steps", "5", "--quiet"}, dir).code, 0);
  Result bad = run_moreau({"run", scene.string(), "--restart", "plain.h5", "--out", "x.h5"}, dir);
  EXPECT_EQ(bad.code, 2) << bad.err;
  EXPECT_NE(bad.err.find("at /frames/00000005/contacts/bond: missing: the scene's contact laws keep 'bond' per contact"),
            std::string::npos)
      << bad.err;
}
