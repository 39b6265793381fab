// Building a world loads only the plugins the scene names; progress output.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

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

namespace {
std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto p = text.find(what); p != std::string::npos; p = text.find(what, p + 1)) ++n;
  return n;
}
}  // namespace

// The last line once (update() at the last step drew it already); a redrawn bar erases the
// rest of its line (ESC [K), so a shorter line leaves nothing of a longer one; a message
// printed during a run first erases the bar.
TEST(Progress, LastLineOnceAndNoStaleText) {
  std::ostringstream log;
  moreau::kernel::Progress lines(log, false, 0, 100);
  for (long s = 1; s <= 100; ++s) lines.update(s, s * 0.01);
  lines.finish(100, 1.0);
  EXPECT_EQ(count(log.str(), "100.0%"), 1u) << log.str();

  std::ostringstream tty;
  moreau::kernel::Progress bar(tty, true, 0, 100);
  for (long s : {10L, 50L, 100L}) {
    std::this_thread::sleep_for(std::chrono::milliseconds(110));  // the bar redraws at most every 100 ms
    bar.update(s, s * 0.01);
  }
  bar.finish(100, 1.0);
  const std::string out = tty.str();
  EXPECT_EQ(count(out, "100.0%"), 1u) << out;
  EXPECT_EQ(count(out, "\r["), 3u) << out;
  for (auto p = out.find('\r', 1); p != std::string::npos; p = out.find('\r', p + 1))
    EXPECT_EQ(out.substr(p - 3, 3), "\033[K") << "each drawn line erases what was left after it";
  EXPECT_EQ(out.substr(out.size() - 4), "\033[K\n") << "the last line ends the bar";
  EXPECT_EQ(count(out, "\n"), 1u);

  std::ostringstream tty2;
  moreau::kernel::Progress bar2(tty2, true, 0, 100);
  std::this_thread::sleep_for(std::chrono::milliseconds(110));
  bar2.update(30, 0.3);
  bar2.clear_line();
  EXPECT_EQ(tty2.str().substr(tty2.str().size() - 4), "\r\033[K") << "a message starts on an erased line";
}
