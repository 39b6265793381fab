// `polygon-segment`: separating axes against the rounded segment, edge clipping (2 points for a face contact)
#include <convex.hpp>
#include <moreau/detector.hpp>

namespace {
using namespace moreau;

class PolygonSegment : public Detector {
 public:
  static Schema schema() { return {}; }
  static constexpr const char* doc = "separating axes against the rounded segment, edge clipping (2 points for a face contact)";
  PolygonSegment(const Params&, const BuildContext&) {}
  void detect(int, const Shape& first, const Pose& a, const Shape& second, const Pose& b, double alert,
              std::vector<ContactPoint>& out) const override {
    geom::polygon_polygon(geom::polygon_at(first.geometry(), a), geom::segment_at(second.geometry(), b), alert, out);
  }
};
MOREAU_REGISTER(PolygonSegment, "polygon-segment")
}  // namespace
MOREAU_PLUGIN_LIBRARY("moreau_detector_polygon-segment")
