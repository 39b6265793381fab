#pragma once
// A block on an incline of angle alpha, shared by the Coulomb (test_blocks.cpp) and bonded
// (test_cohesion.cpp) incline validations: 2D, a 0.2 × 0.1 polygon on a long slab whose top
// face passes through the origin; 3D, a 0.2 × 0.2 × 0.1 box on a plane. Density 1000,
// h = 1e-3 for 0.5 s, nlgs to 1e-12, a frame every 100 steps; the block is body 1, in
// group "block", the slope in group "slope", their interaction uses the law "law".
#include <cmath>
#include <sstream>
#include <string>

#include "run_scene.hpp"

namespace moreau_test {

/// `law_json`: the law's JSON object, e.g. {"type": "coulomb", "friction": 0.3}.
inline SceneRun run_block_on_incline(const std::string& name, int dim, double alpha, const std::string& law_json) {
  std::ostringstream s;
  s.precision(17);
  const double nx = std::sin(alpha), nz = std::cos(alpha);  // incline normal
  s << R"({"format": "moreau-scene/1", "dimension": )" << dim << R"(, "time": {"step": 1e-3, "duration": 0.5},
  "gravity": )" << (dim == 2 ? "[0, -9.81]" : "[0, 0, -9.81]") << R"(, "materials": {"m": {"density": 1000}},
  "laws": {"law": )" << law_json << R"(},
  "interactions": [{"groups": ["block", "slope"], "law": "law"}],
  "solver": {"type": "nlgs", "tolerance": 1e-12, "max_iterations": 500}, "output": {"every": 100}, "bodies": [)";
  if (dim == 2) {
    s << R"({"name": "slope", "fixed": true, "position": [)" << -0.1 * nx << ", " << -0.1 * nz << R"(], "angle": )" << -alpha
      << R"(, "contactors": [{"shape": "polygon", "vertices": [[-10, -0.1], [10, -0.1], [10, 0.1], [-10, 0.1]], "group": "slope"}]},
      {"name": "block", "material": "m", "position": [)" << 0.05 * nx << ", " << 0.05 * nz << R"(], "angle": )" << -alpha
      << R"(, "contactors": [{"shape": "polygon", "vertices": [[-0.1, -0.05], [0.1, -0.05], [0.1, 0.05], [-0.1, 0.05]], "group": "block"}]}]})";
  } else {
    s << R"({"name": "slope", "fixed": true, "position": [0, 0, 0], "contactors": [{"shape": "plane", "normal": [)" << nx
      << ", 0, " << nz << R"(], "group": "slope"}]},
      {"name": "block", "material": "m", "position": [)" << 0.05 * nx << ", 0, " << 0.05 * nz << R"(], "orientation": [)"
      << std::cos(alpha / 2) << ", 0, " << std::sin(alpha / 2) << R"(, 0],
       "contactors": [{"shape": "box", "size": [0.2, 0.2, 0.1], "group": "block"}]}]})";
  }
  return run_scene(name, s.str());
}

/// The block's downhill speed in frame `f` of such a run.
inline double downhill_speed(const SceneRun& run, const std::string& f, int dim, double alpha) {
  const auto v = run.at(f, "velocity");
  const double vx = v[dim], vz = v[dim + dim - 1];  // the block is body 1
  return vx * std::cos(alpha) - vz * std::sin(alpha);
}

}  // namespace moreau_test
