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

/// Rigid and elastic bodies in one run (issue 12): an elastic slab on a rigid floor (its
/// bottom nodes against the floor, its top edges under the disks), two rigid disks falling
/// on it. `extra_top` adds top-level keys (after a comma).
inline std::string slab_and_disks_scene(double duration, const std::string& extra_top = "") {
  return R"({
  "format": "moreau-scene/1",
  "dimension": 2,
  "time": {"step": 0.001, "duration": )" + std::to_string(duration) + R"(, "theta": 0.5},
  "gravity": [0, -9.81],
  "materials": {"soft": {"density": 1000, "young": 1e6, "poisson": 0.3}, "hard": {"density": 2000}},
  "laws": {"rough": {"type": "coulomb", "friction": 0.3}},
  "bodies": [
    {"name": "floor", "fixed": true, "position": [0, -0.01], "contactors": [{"shape": "segment", "length": 1, "thickness": 0.02, "group": "floor"}]},
    {"name": "slab", "model": "elastic", "material": "soft", "rayleigh_beta": 1e-3,
     "mesh": {"generate": "rectangle", "origin": [-0.2, 0], "extent": [0.4, 0.05], "size": 0.025},
     "contactors": [{"shape": "point", "boundary": "ymin", "group": "slab_bottom"}, {"shape": "edge", "boundary": "ymax", "group": "slab_top"}]},
    {"name": "a", "material": "hard", "position": [-0.05, 0.09], "contactors": [{"shape": "disk", "radius": 0.03, "group": "disk"}]},
    {"name": "b", "material": "hard", "position": [0.06, 0.15], "angular_velocity": 3, "contactors": [{"shape": "disk", "radius": 0.03, "group": "disk"}]}
  ],
  "interactions": [{"groups": ["slab_bottom", "floor"], "law": "rough"}, {"groups": ["disk", "slab_top"], "law": "rough"}],
  "output": {"file": "out.h5", "every": 10})" + extra_top + R"(
})";
}

}  // namespace moreau_test
