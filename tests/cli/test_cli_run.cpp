// Running scenes from the command line: output, progress, timings, plugin listing.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "cli_runner.hpp"
#include "h5_read.hpp"
#include "scenes.hpp"

namespace fs = std::filesystem;
using namespace moreau_test;

TEST(CliRun, ProjectileRunsAndWritesFrames) {
  const fs::path dir = scratch_dir("projectile");
  const fs::path scene = write_file(dir, "scene.json", projectile_scene());
  Result r = run_moreau({"run", scene.string()}, dir);
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string out = (dir / "out.h5").string();
  ASSERT_TRUE(fs::exists(out));
  EXPECT_NE(r.out.find(out), std::string::npos) << "must say where the output went: " << r.out;
  // 20 steps, a frame every 5 plus the first: 0, 5, 10, 15, 20.
  EXPECT_EQ(frame_names(out), (std::vector<std::string>{"00000000", "00000005", "00000010", "00000015", "00000020"}));
  // θ = 0.5 integrates constant gravity exactly: x = x0 + v0 t + g t²/2.
  const auto p = read_doubles(out, "/frames/00000020/position");
  ASSERT_EQ(p.size(), 4u);
  const double t = 0.2;
  EXPECT_NEAR(p[0], 0 + 2 * t, 1e-12);
  EXPECT_NEAR(p[1], 1 + 3 * t - 0.5 * 9.81 * t * t, 1e-12);
  EXPECT_EQ(p[2], 1.0);  // the fixed wall has not moved
  EXPECT_EQ(p[3], 0.0);
  const auto a = read_doubles(out, "/frames/00000020/angle");
  EXPECT_NEAR(a[0], 1.5 * t, 1e-12);
  // Not a terminal: periodic progress lines, then the per-stage timings.
  EXPECT_NE(r.err.find("progress: 100.0%"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("update_dofs"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("narrow_phase"), std::string::npos) << "a stage with no work is not run nor shown:\n" << r.err;
}

TEST(CliRun, StepsOptionLimitsTheRun) {
  const fs::path dir = scratch_dir("steps");
  const fs::path scene = write_file(dir, "scene.json", projectile_scene());
  Result r = run_moreau({"run", scene.string(), "--steps", "7", "--out", "short.h5", "--quiet"}, dir);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(r.err.empty()) << r.err;
  EXPECT_EQ(frame_names((dir / "short.h5").string()), (std::vector<std::string>{"00000000", "00000005", "00000007"}));
}

TEST(CliRun, CheckAcceptsAValidScene) {
  const fs::path dir = scratch_dir("check");
  const fs::path scene = write_file(dir, "scene.json", projectile_scene());
  Result r = run_moreau({"check", scene.string()}, dir);
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("valid scene"), std::string::npos);
  EXPECT_FALSE(fs::exists(dir / "out.h5")) << "check writes nothing";
}

TEST(CliRun, PluginsListsKindsNamesAndParameters) {
  Result r = run_moreau({"plugins", "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  auto j = nlohmann::json::parse(r.out);
  ASSERT_TRUE(j.contains("modelization"));
  ASSERT_TRUE(j.contains("integrator"));
  bool rigid = false;
  for (const auto& m : j["modelization"])
    if (m["name"] == "rigid") {
      rigid = true;
      EXPECT_FALSE(m["fields"].empty());
      EXPECT_FALSE(m["body_parameters_2d"].empty());
    }
  EXPECT_TRUE(rigid);
  // The kernel's own sets, from the same tables: the contacts' impulse persists and restarts.
  ASSERT_TRUE(j.contains("kernel"));
  bool impulse = false;
  for (const auto& f : j["kernel"][0]["fields"])
    if (f["set"] == "contacts" && f["name"] == "impulse") impulse = f["persist"] == true && f["restart"] == true;
  EXPECT_TRUE(impulse);
  for (const auto& m : j["modelization"])
    if (m["name"] == "rigid") {
      EXPECT_EQ(m["node_set"], "rigid.nodes");
      EXPECT_EQ(m["default_integrator"], "theta");
    }
  Result text = run_moreau({"plugins"});
  EXPECT_EQ(text.code, 0);
  EXPECT_NE(text.out.find("integrator:"), std::string::npos);
  EXPECT_NE(text.out.find("theta"), std::string::npos);
}
