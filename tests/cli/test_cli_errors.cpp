// Bad input: exit code 2, one clear message naming the file and the JSON pointer, and
// no output file left behind.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "bad_input.hpp"
#include "cli_runner.hpp"
#include "scenes.hpp"

namespace fs = std::filesystem;
using namespace moreau_test;

TEST(CliErrors, MalformedJson) {
  expect_bad_input("malformed", replace(projectile_scene(), "\"dimension\": 2,", "\"dimension\": 2,,"),
                   "malformed JSON at line 3, column 18");
}

TEST(CliErrors, WrongType) {
  expect_bad_input("type", replace(projectile_scene(), "\"step\": 0.01", "\"step\": \"fast\""),
                   "at /time/step: expected a number, got a string");
}

TEST(CliErrors, MissingRequiredKey) {
  expect_bad_input("missing", replace(projectile_scene(), "\"position\": [0, 1], ", ""),
                   "at /bodies/0/position: missing required key \"position\"");
}

TEST(CliErrors, OutOfRange) {
  expect_bad_input("range", projectile_scene("", "\"step\": 0.01, \"duration\": 0.2, \"theta\": 2"),
                   "at /time/theta: value 2 out of range: expected >= 0.5 and <= 1");
}

TEST(CliErrors, UnknownKeySuggestsNearest) {
  expect_bad_input("unknown", replace(projectile_scene(), "\"gravity\"", "\"gravty\""),
                   "at /gravty: unknown key \"gravty\"; did you mean \"gravity\"?");
}

TEST(CliErrors, UnknownPluginListsValidNames) {
  expect_bad_input("plugin", projectile_scene(",\n  \"forces\": [{\"type\": \"antigravity\"}]"),
                   "at /forces/0/type: unknown force 'antigravity'; valid names: ");
}

TEST(CliErrors, BrokenPluginFile) {
  const fs::path dir = scratch_dir("broken_plugin");
  fs::create_directories(dir / "plugins");
  {
    std::ofstream f(dir / "plugins" / "libmoreau_force_broken.so");
    for (int i = 0; i < 100; ++i) f << "not a shared library\n";
  }
  const fs::path scene = write_file(
      dir, "scene.json", projectile_scene(",\n  \"plugin_paths\": [\"plugins\"],\n  \"forces\": [{\"type\": \"broken\"}]"));
  Result r = run_moreau({"run", scene.string()}, dir);
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("at /forces/0/type: failed to load plugin library"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("libmoreau_force_broken.so"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "out.h5"));
}

TEST(CliErrors, AbiMismatchedPluginIsRefused) {
  const fs::path dir = scratch_dir("abi_plugin");
  const fs::path scene = write_file(dir, "scene.json",
                                    projectile_scene(",\n  \"plugin_paths\": [\"" MOREAU_TEST_PLUGINS "/abi\"],\n"
                                                     "  \"forces\": [{\"type\": \"abi\"}]"));
  Result r = run_moreau({"run", scene.string()}, dir);
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("plugin ABI mismatch"), std::string::npos) << r.err;
}

TEST(CliErrors, EveryErrorReportedAtOnce) {
  std::string s = replace(projectile_scene(), "\"step\": 0.01", "\"step\": -1");
  s = replace(s, "\"gravity\"", "\"gravty\"");
  const fs::path dir = scratch_dir("all");
  const fs::path scene = write_file(dir, "scene.json", s);
  Result r = run_moreau({"check", scene.string()}, dir);
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("at /time/step: value -1 out of range: expected > 0"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("at /gravty: unknown key"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("2 errors"), std::string::npos) << r.err;
}

TEST(CliErrors, UnwritableOutputPath) {
  const fs::path dir = scratch_dir("unwritable");
  const fs::path scene = write_file(dir, "scene.json", projectile_scene());
  Result r = run_moreau({"run", scene.string(), "--out", "/nonexistent-folder/sub/out.h5"}, dir);
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("/nonexistent-folder/sub/out.h5"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists("/nonexistent-folder"));
}

TEST(CliErrors, MissingSceneFile) {
  Result r = run_moreau({"run", "/nonexistent/scene.json"});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("/nonexistent/scene.json: cannot open the file for reading"), std::string::npos) << r.err;
}

TEST(CliErrors, UsageErrorsExitTwo) {
  EXPECT_EQ(run_moreau({"run"}).code, 2);
  EXPECT_EQ(run_moreau({"frobnicate"}).code, 2);
  EXPECT_EQ(run_moreau({}).code, 2);
}
