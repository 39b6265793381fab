// `convex-plane`: every corner within the alert distance of the half-space (a resting face gives 4 points)
#include <convex.hpp>
#include <moreau/detector.hpp>

namespace {
using namespace moreau;

class ConvexPlane : public Detector {
 public:
  static Schema schema() { return {}; }
  static constexpr const char* doc = "every corner within the alert distance of the half-space (a resting face gives 4 points)";
  ConvexPlane(const Params&, const BuildContext&) {}
  void detect(int, const Shape& first, const Pose& a, const Shape& second, const Pose& b, double alert,
              std::vector<ContactPoint>& out) const override {
    const geom::V3 n = geom::rotate(b.rotation, geom::V3{second.geometry()[0], second.geometry()[1], second.geometry()[2]});
    geom::polyhedron_plane(geom::polyhedron_at(first.shape_name(), first.geometry(), a), n,
                           geom::V3{b.position[0], b.position[1], b.position[2]}, alert, out);
  }
};
MOREAU_REGISTER(ConvexPlane, "convex-plane")
}  // namespace
MOREAU_PLUGIN_LIBRARY("moreau_detector_convex-plane")
