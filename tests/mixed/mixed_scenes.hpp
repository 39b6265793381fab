#pragma once
// Mixed scenes for the tests: rigid bodies and chains (tests/mixed/chain_fields.hpp) in
// one run. A chain of four beads (a disk or sphere contactor on each node, springs between
// consecutive nodes) lies on a rigid floor; a rigid ball rests on its two middle beads; a
// rigid box (2D: a polygon) flies free, far away, to be pushed by a force or watched by a
// hook. The plugins of the chain are in MOREAU_TEST_PLUGINS/mixed.
#include <cmath>
#include <sstream>
#include <string>

namespace moreau_test {

/// `solver`: the scene's solver object; `extra`: more top-level keys (",\"forces\": …").
inline std::string mixed_scene(int d, const std::string& solver = R"({"type": "auto", "tolerance": 1e-10})",
                               double duration = 0.1, int every = 1, const std::string& extra = "",
                               double step = 0.001) {
  const double r = 0.05, R = 0.1;
  // The ball touches beads 1 and 2 (x = ∓0.1): centre height 0.01 + r + √((r+R)² − 0.1²).
  const double bead_y = 0.01 + r, ball_y = bead_y + std::sqrt((r + R) * (r + R) - 0.01);
  std::ostringstream s;
  s.precision(17);
  auto v = [&](double x, double y) {
    std::ostringstream o;
    o.precision(17);
    if (d == 2) o << "[" << x << ", " << y << "]";
    else o << "[" << x << ", " << y << ", 0]";
    return o.str();
  };
  const std::string bead = d == 2 ? "disk" : "sphere";
  s << R"({"format": "moreau-scene/1", "dimension": )" << d << R"(,
  "plugin_paths": [")" << MOREAU_TEST_PLUGINS << R"(/mixed"],
  "time": {"step": )" << step << R"(, "duration": )" << duration << R"(, "theta": 0.5},
  "gravity": )" << v(0, -9.81) << R"(,
  "materials": {"ball": {"density": 100}},
  "laws": {"rough": {"type": "coulomb", "friction": 0.3}},
  "bodies": [
    {"name": "floor", "fixed": true, "position": )" << v(0, 0) << R"(, "contactors": [)"
    << (d == 2 ? R"({"shape": "segment", "length": 4, "thickness": 0.02, "group": "floor"})"
               : R"({"shape": "plane", "normal": [0, 1, 0], "group": "floor", "offset": [0, 0.01, 0]})")
    << R"(]},
    {"name": "chain", "model": "chain", "node_mass": 1.0, "stiffness": 2000,
     "nodes": [)" << v(-0.3, bead_y) << ", " << v(-0.1, bead_y) << ", " << v(0.1, bead_y) << ", " << v(0.3, bead_y) << R"(],
     "contactors": [)";
  for (int i = 0; i < 4; ++i)
    s << (i ? ", " : "") << R"({"shape": ")" << bead << R"(", "radius": )" << r << R"(, "node": )" << i
      << R"(, "group": "bead"})";
  s << R"(]},
    {"name": "ball", "material": "ball", "position": )" << v(0, ball_y) << R"(,
     "contactors": [{"shape": ")" << bead << R"(", "radius": )" << R << R"(, "group": "ball"}]},
    {"name": "flyer", "mass": 2.0, "inertia": )" << (d == 2 ? "0.1" : "[0.1, 0.2, 0.3]") << R"(, "position": )"
    << v(5, 5) << R"(}
  ],
  "interactions": [{"groups": ["bead", "floor"], "law": "rough"}, {"groups": ["ball", "bead"], "law": "rough"},
                   {"groups": ["ball", "floor"], "law": "rough"}],
  "solver": )" << solver << R"(,
  "output": {"every": )" << every << R"(})" << extra << "}";
  return s.str();
}

}  // namespace moreau_test
