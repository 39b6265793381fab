#pragma once
// Runs scenes (given as JSON) through `moreau run` and reads their frames, for the
// analysis tests.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "h5_read.hpp"

namespace moreau_test {

using nlohmann::json;

struct SceneRun {
  std::string file;
  std::vector<std::string> frames;
  std::vector<double> at(const std::string& frame, const std::string& path) const {
    return read_doubles(file, "/frames/" + frame + "/" + path);
  }
  double scalar(const std::string& frame, const std::string& path) const { return at(frame, path).at(0); }
  std::vector<double> header(const std::string& path) const { return read_doubles(file, path); }
  const std::string& last() const { return frames.back(); }
};

inline SceneRun run_json(const std::string& name, const json& scene, const std::vector<std::string>& extra = {}) {
  const auto dir = scratch_dir(name);
  const auto path = write_file(dir, "scene.json", scene.dump(1));
  std::vector<std::string> args{"run", path.string(), "--out", "out.h5", "--quiet"};
  args.insert(args.end(), extra.begin(), extra.end());
  Result r = run_moreau(args, dir);
  EXPECT_EQ(r.code, 0) << r.err;
  SceneRun run;
  run.file = (dir / "out.h5").string();
  if (r.code == 0) run.frames = frame_names(run.file);
  return run;
}

/// `moreau run` and `moreau check` refuse the scene at `path` (in `dir`): exit 2, the file
/// and `where` (a JSON pointer) named, `what` said, and no output left behind.
inline void expect_input_error(const std::filesystem::path& dir, const std::filesystem::path& path, const std::string& where,
                               const std::string& what) {
  for (const char* cmd : {"run", "check"}) {
    Result r = run_moreau({cmd, path.string()}, dir);
    EXPECT_EQ(r.code, 2) << cmd << ": " << r.err;
    EXPECT_NE(r.err.find(path.string() + ": at " + where + ": "), std::string::npos) << "expected " << where << ":\n" << r.err;
    EXPECT_NE(r.err.find(what), std::string::npos) << "expected: " << what << "\n" << r.err;
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "out.h5"));
}

/// A 2D scene with a floor (group "wall") and the interactions of "grain" with itself and
/// the floor, no other bodies: tests add theirs.
inline json floor_scene_2d() {
  return json::parse(R"({"format": "moreau-scene/1", "dimension": 2, "time": {"step": 1e-3, "duration": 0.01},
    "gravity": [0, -9.81], "materials": {"m": {"density": 1000}},
    "laws": {"l": {"type": "coulomb", "friction": 0.3}},
    "bodies": [{"name": "floor", "fixed": true, "position": [0, -0.01],
                "contactors": [{"shape": "segment", "length": 0.2, "thickness": 0.02, "group": "wall"}]}],
    "interactions": [{"groups": ["grain", "grain"], "law": "l"}, {"groups": ["grain", "wall"], "law": "l"}],
    "output": {"every": 10}})");
}

inline json read_config(const std::string& name) {
  std::ifstream in(std::string(MOREAU_SOURCE_DIR) + "/configs/" + name);
  return json::parse(in);
}

}  // namespace moreau_test
