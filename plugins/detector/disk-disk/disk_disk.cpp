// `disk-disk` and `sphere-sphere` share this closed form: centres distance minus radii;
// so do `point-disk` and `point-sphere` (a mesh node: radius 0).
#include <cmath>
#include <moreau/detector.hpp>

namespace {
using namespace moreau;

class RoundRound : public Detector {
 public:
  static Schema schema() { return {}; }
  static constexpr const char* doc = "closed form for two round shapes (disks or spheres)";
  RoundRound(const Params&, const BuildContext&) {}
  void detect(int dim, const Shape& s1, const Pose& a, const Shape& s2, const Pose& b, double alert,
              std::vector<ContactPoint>& out) const override {
    const double r1 = s1.geometry()[0], r2 = s2.geometry()[0];
    double n[3] = {0, 0, 0}, d2 = 0;
    for (int k = 0; k < dim; ++k) {
      n[k] = a.position[k] - b.position[k];
      d2 += n[k] * n[k];
    }
    const double d = std::sqrt(d2);
    const double gap = d - r1 - r2;
    if (gap > alert) return;
    if (d > 0) for (int k = 0; k < dim; ++k) n[k] /= d;
    else n[dim - 1] = 1;  // coincident centres: any direction, a fixed one
    ContactPoint c;
    for (int k = 0; k < 3; ++k) {
      c.normal[k] = n[k];
      c.point[k] = k < dim ? b.position[k] + n[k] * (r2 + gap / 2) : 0.0;
    }
    c.gap = gap;
    out.push_back(c);
  }
};
MOREAU_REGISTER(RoundRound, DETECTOR_NAME)
}  // namespace
MOREAU_PLUGIN_LIBRARY("moreau_detector_" DETECTOR_NAME)
