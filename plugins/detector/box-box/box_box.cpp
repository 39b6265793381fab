// `box-box`: separating axes; a face contact is clipped into a manifold of up to 4 points
#include <convex.hpp>
#include <moreau/detector.hpp>

namespace {
using namespace moreau;

class BoxBox : public Detector {
 public:
  static Schema schema() { return {}; }
  static constexpr const char* doc = "separating axes; a face contact is clipped into a manifold of up to 4 points";
  BoxBox(const Params&, const BuildContext&) {}
  void detect(int, const Shape& first, const Pose& a, const Shape& second, const Pose& b, double alert,
              std::vector<ContactPoint>& out) const override {
    geom::polyhedron_polyhedron(geom::polyhedron_at(first.shape_name(), first.geometry(), a),
                                geom::polyhedron_at(second.shape_name(), second.geometry(), b), alert, out);
  }
};
MOREAU_REGISTER(BoxBox, "box-box")
}  // namespace
MOREAU_PLUGIN_LIBRARY("moreau_detector_box-box")
