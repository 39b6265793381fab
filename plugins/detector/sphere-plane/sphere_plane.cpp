// `sphere-plane`: signed distance of the sphere's centre to the plane, minus the radius.
// Also `point-plane` (a mesh node: a sphere of radius 0).
#include <moreau/detector.hpp>

namespace {
using namespace moreau;

class SpherePlane : public Detector {
 public:
  static Schema schema() { return {}; }
  static constexpr const char* doc = "closed form: sphere against half-space";
  SpherePlane(const Params&, const BuildContext&) {}
  void detect(int, const Shape& sphere, const Pose& a, const Shape& plane, const Pose& b, double alert,
              std::vector<ContactPoint>& out) const override {
    const double R = sphere.geometry()[0];
    const double* nb = plane.geometry().data();
    // World normal: rotate the body-frame normal by the plane body's quaternion.
    const double* q = b.rotation;
    const double u[3] = {q[1], q[2], q[3]};
    const double t[3] = {2 * (u[1] * nb[2] - u[2] * nb[1]), 2 * (u[2] * nb[0] - u[0] * nb[2]), 2 * (u[0] * nb[1] - u[1] * nb[0])};
    const double n[3] = {nb[0] + q[0] * t[0] + (u[1] * t[2] - u[2] * t[1]), nb[1] + q[0] * t[1] + (u[2] * t[0] - u[0] * t[2]),
                         nb[2] + q[0] * t[2] + (u[0] * t[1] - u[1] * t[0])};
    double s = 0;
    for (int k = 0; k < 3; ++k) s += (a.position[k] - b.position[k]) * n[k];
    const double gap = s - R;
    if (gap > alert) return;
    ContactPoint c;
    for (int k = 0; k < 3; ++k) {
      c.normal[k] = n[k];
      c.point[k] = a.position[k] - n[k] * (R + gap / 2);
    }
    c.gap = gap;
    out.push_back(c);
  }
};
MOREAU_REGISTER(SpherePlane, DETECTOR_NAME)
}  // namespace
MOREAU_PLUGIN_LIBRARY("moreau_detector_" DETECTOR_NAME)
