#pragma once
// Checks of bad input as users meet it: exit code 2, one clear message naming the file
// and the JSON pointer, and no output file left behind.
#include <gtest/gtest.h>

#include <filesystem>
#include <stdexcept>
#include <string>

#include "cli_runner.hpp"

namespace moreau_test {

/// Runs `moreau run` and `moreau check` on `scene_text`; expects exit 2, `expected` in
/// stderr, the file named, no output, and no "internal error".
inline void expect_bad_input(const std::string& name, const std::string& scene_text, const std::string& expected) {
  namespace fs = std::filesystem;
  const fs::path dir = scratch_dir(name);
  const fs::path scene = write_file(dir, "scene.json", scene_text);
  Result r = run_moreau({"run", scene.string()}, dir);
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find(scene.string() + ": "), std::string::npos) << "message must name the file:\n" << r.err;
  EXPECT_NE(r.err.find(expected), std::string::npos) << "expected: " << expected << "\ngot:\n" << r.err;
  EXPECT_EQ(r.err.find("internal error"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "out.h5")) << "bad input must leave no output";
  Result c = run_moreau({"check", scene.string()}, dir);
  EXPECT_EQ(c.code, 2) << c.err;
  EXPECT_NE(c.err.find(expected), std::string::npos) << c.err;
}

/// `s` with the first `from` replaced by `to` (which must be there).
inline std::string replace(std::string s, const std::string& from, const std::string& to) {
  const auto p = s.find(from);
  if (p == std::string::npos) throw std::logic_error("scene template has no " + from);
  return s.replace(p, from.size(), to);
}

}  // namespace moreau_test
