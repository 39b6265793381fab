#pragma once
// Small scenes for the command-line tests.
#include <string>

namespace moreau_test {

/// A 2D projectile: one rigid body under gravity, with an explicit mass and inertia.
inline std::string projectile_scene(const std::string& extra_top = "", const std::string& time = "\"step\": 0.01, \"duration\": 0.2") {
  return R"({
  "format": "moreau-scene/1",
  "dimension": 2,
  "time": {)" + time + R"(},
  "gravity": [0, -9.81],
  "bodies": [
    {"name": "ball", "position": [0, 1], "velocity": [2, 3], "angular_velocity": 1.5, "mass": 2.0, "inertia": 0.1},
    {"name": "wall", "fixed": true, "position": [1, 0]}
  ],
  "output": {"file": "out.h5", "every": 5})" + extra_top + R"(
})";
}

}  // namespace moreau_test
