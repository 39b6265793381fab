// `sphere-box`: closest point of the polyhedron (box or convex) to the sphere centre.
// Also `sphere-convex`, `point-box` and `point-convex` (a mesh node: a sphere of radius 0).
#include <convex.hpp>
#include <moreau/detector.hpp>

namespace {
using namespace moreau;

class SphereBox : public Detector {
 public:
  static Schema schema() { return {}; }
  static constexpr const char* doc = "closest point of the polyhedron to the sphere centre";
  SphereBox(const Params&, const BuildContext&) {}
  void detect(int, const Shape& first, const Pose& a, const Shape& second, const Pose& b, double alert,
              std::vector<ContactPoint>& out) const override {
    geom::sphere_polyhedron({a.position[0], a.position[1], a.position[2]}, first.geometry()[0],
                            geom::polyhedron_at(second.shape_name(), second.geometry(), b), alert, out);
  }
};
MOREAU_REGISTER(SphereBox, DETECTOR_NAME)
}  // namespace
MOREAU_PLUGIN_LIBRARY("moreau_detector_" DETECTOR_NAME)
