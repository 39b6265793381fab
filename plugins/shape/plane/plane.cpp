// `plane` (3D): the half-space below the plane through the body origin with outward
// `normal` (body frame). Unbounded: no mass properties (a fixed or explicitly weighed body).
#include <cmath>
#include <limits>
#include <moreau/shape.hpp>

namespace {
using namespace moreau;

class Plane : public Shape {
 public:
  static Schema schema() {
    Schema s;
    s.vector("normal", "outward normal, body frame (normalised)", 3).fallback({0.0, 0.0, 1.0});
    s.dimensions({3});
    return s;
  }
  static constexpr const char* doc = "half-space (3D floors and walls)";
  Plane(const Params& p, const BuildContext&) : g_(p.vector("normal")) {
    const double n = std::sqrt(g_[0] * g_[0] + g_[1] * g_[1] + g_[2] * g_[2]);
    if (!(n > 1e-12)) throw p.error("normal", "the normal must not be zero");
    for (double& x : g_) x /= n;
  }
  const char* shape_name() const override { return "plane"; }
  const std::vector<double>& geometry() const override { return g_; }
  bool has_mass() const override { return false; }
  MassProperties mass_properties() const override { return {}; }
  void bounds(int, const Pose&, double lo[3], double hi[3]) const override {
    const double inf = std::numeric_limits<double>::infinity();
    for (int k = 0; k < 3; ++k) {
      lo[k] = -inf;
      hi[k] = inf;
    }
  }

 private:
  std::vector<double> g_;
};
MOREAU_REGISTER(Plane, "plane")
}  // namespace
MOREAU_PLUGIN_LIBRARY("moreau_shape_plane")
