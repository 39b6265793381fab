// `disk-polygon`: closest point of the polygon to the disk centre
// Also `point-polygon` (a mesh node: a disk of radius 0).
#include <convex.hpp>
#include <moreau/detector.hpp>

namespace {
using namespace moreau;

class DiskPolygon : public Detector {
 public:
  static Schema schema() { return {}; }
  static constexpr const char* doc = "closest point of the polygon to the disk centre";
  DiskPolygon(const Params&, const BuildContext&) {}
  void detect(int, const Shape& first, const Pose& a, const Shape& second, const Pose& b, double alert,
              std::vector<ContactPoint>& out) const override {
    geom::disk_polygon({a.position[0], a.position[1]}, first.geometry()[0], geom::polygon_at(second.geometry(), b), alert, out);
  }
};
MOREAU_REGISTER(DiskPolygon, DETECTOR_NAME)
}  // namespace
MOREAU_PLUGIN_LIBRARY("moreau_detector_" DETECTOR_NAME)
