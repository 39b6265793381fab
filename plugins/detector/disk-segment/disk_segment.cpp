// `disk-segment`: a disk against a rounded segment: distance from the disk centre to the
// Also `point-segment` (a mesh node: a disk of radius 0).
// segment's core, minus the radius and half the thickness.
#include <algorithm>
#include <cmath>
#include <moreau/detector.hpp>

namespace {
using namespace moreau;

class DiskSegment : public Detector {
 public:
  static Schema schema() { return {}; }
  static constexpr const char* doc = "closed form: disk against rounded segment";
  DiskSegment(const Params&, const BuildContext&) {}
  void detect(int, const Shape& disk, const Pose& a, const Shape& seg, const Pose& b, double alert,
              std::vector<ContactPoint>& out) const override {
    const double R = disk.geometry()[0], L = seg.geometry()[0], r = seg.geometry()[1] / 2;
    const double ex = std::cos(b.rotation[0]), ey = std::sin(b.rotation[0]);
    const double dx = a.position[0] - b.position[0], dy = a.position[1] - b.position[1];
    const double s = std::clamp(dx * ex + dy * ey, -L / 2, L / 2);  // closest point on the core
    const double px = b.position[0] + s * ex, py = b.position[1] + s * ey;
    double nx = a.position[0] - px, ny = a.position[1] - py;
    const double d = std::hypot(nx, ny);
    const double gap = d - R - r;
    if (gap > alert) return;
    if (d > 0) {
      nx /= d;
      ny /= d;
    } else {
      nx = -ey;  // centre on the core: the segment's own normal
      ny = ex;
    }
    ContactPoint c;
    c.normal[0] = nx;
    c.normal[1] = ny;
    c.point[0] = px + nx * (r + gap / 2);
    c.point[1] = py + ny * (r + gap / 2);
    c.gap = gap;
    out.push_back(c);
  }
};
MOREAU_REGISTER(DiskSegment, DETECTOR_NAME)
}  // namespace
MOREAU_PLUGIN_LIBRARY("moreau_detector_" DETECTOR_NAME)
