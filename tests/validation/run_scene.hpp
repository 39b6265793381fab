#pragma once
// Runs a scene given as text and reads its frames.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "h5_read.hpp"

namespace moreau_test {

struct SceneRun {
  std::string file;
  std::string err;  ///< what the run printed on stderr
  std::vector<std::string> frames;
  std::vector<double> at(const std::string& frame, const std::string& dataset) const {
    return read_doubles(file, "/frames/" + frame + "/" + dataset);
  }
};

/// printf into a string: scenes written as format strings.
inline std::string format(const char* fmt, auto... args) {
  char buf[8192];
  std::snprintf(buf, sizeof buf, fmt, args...);
  return buf;
}

/// Observed order of convergence from errors e1, e2 at sizes s1 > s2.
inline double order(double e1, double e2, double s1, double s2) { return std::log(e1 / e2) / std::log(s1 / s2); }

inline SceneRun run_scene(const std::string& name, const std::string& scene) {
  const auto dir = scratch_dir(name);
  const auto path = write_file(dir, "scene.json", scene);
  Result r = run_moreau({"run", path.string(), "--out", "out.h5", "--quiet"}, dir);
  EXPECT_EQ(r.code, 0) << r.err;
  SceneRun run;
  run.file = (dir / "out.h5").string();
  run.err = r.err;
  run.frames = frame_names(run.file);
  return run;
}

}  // namespace moreau_test
