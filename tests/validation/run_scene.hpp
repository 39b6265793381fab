#pragma once
// Runs a scene given as text and reads its frames.
#include <gtest/gtest.h>

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
