// `polygon-polygon`: separating axes and edge clipping (2 points for a face contact)
#include <convex.hpp>
#include <moreau/detector.hpp>

namespace {
using namespace moreau;

class PolygonPolygon : public Detector {
 public:
  static Schema schema() { return {}; }
  static constexpr const char* doc = "separating axes and edge clipping (2 points for a face contact)";
  PolygonPolygon(const Params&, const BuildContext&) {}
  void detect(int, const Shape& first, const Pose& a, const Shape& second, const Pose& b, double alert,
              std::vector<ContactPoint>& out) const override {
    geom::polygon_polygon(geom::polygon_at(first.geometry(), a), geom::polygon_at(second.geometry(), b), alert, out);
  }
};
MOREAU_REGISTER(PolygonPolygon, "polygon-polygon")
}  // namespace
MOREAU_PLUGIN_LIBRARY("moreau_detector_polygon-polygon")
