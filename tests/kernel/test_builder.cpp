// Building a world loads only the plugins the scene names; progress output.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "kernel/run/progress.hpp"
#include "kernel/scene/builder.hpp"

namespace fs = std::filesystem;

TEST(Builder, LoadsOnlyThePluginsTheSceneNames) {
  const fs::path scene = fs::temp_directory_path() / "moreau_test_builder.json";
  std::ofstream(scene) << R"({"format": "moreau-scene/1", "dimension": 3, "time": {"step": 0.01, "duration": 0.1},
    "bodies": [{"name": "b", "position": [0, 0, 0], "mass": 1, "inertia": [1, 1, 1]}]})";
  auto world = moreau::kernel::build_world(scene.string());
  std::vector<std::string> loaded;
  for (const auto* e : world->registry->entries()) loaded.push_back(e->registration.name);
  // The installed folder also holds forces, hooks and laws: none of them is loaded.
  EXPECT_EQ(loaded, (std::vector<std::string>{"rigid", "theta"}));
  EXPECT_FALSE(world->registry->available(moreau::Kind::hook).empty()) << "the hooks exist, unloaded";
}

TEST(Progress, BarOnATerminalLinesOtherwise) {
  std::ostringstream tty, log;
  moreau::kernel::Progress bar(tty, true, 0, 100), lines(log, false, 0, 100);
  for (long s = 1; s <= 100; ++s) {
    bar.update(s, s * 0.01);
    lines.update(s, s * 0.01);
  }
  bar.finish(100, 1.0);
  lines.finish(100, 1.0);
  EXPECT_NE(tty.str().find("\r[##############################] 100.0%"), std::string::npos) << tty.str();
  EXPECT_EQ(log.str().find('\r'), std::string::npos);
  EXPECT_NE(log.str().find("progress:  10.0%  step 10/100"), std::string::npos) << log.str();
  EXPECT_NE(log.str().find("progress: 100.0%  step 100/100"), std::string::npos) << log.str();
}
