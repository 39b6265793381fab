// `plane` (3D): the half-space below the plane through the body origin with outward
// `normal` (body frame). Unbounded: no mass properties (a fixed or explicitly weighed body).
#include <cmath>
#include <limits>
#include <moreau/shape.hpp>
#include <utility>

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
  /// A square patch of the plane, centred on the body origin, of half side `extent`, so
  /// that it covers the scene's footprint on the plane at the start.
  DisplayMesh display_mesh(double extent) const override {
    const double n[3] = {g_[0], g_[1], g_[2]};
    // t1: the unit vector orthogonal to n built from the axis least aligned with it; t2 = n × t1.
    const int k = std::fabs(n[0]) <= std::fabs(n[1]) && std::fabs(n[0]) <= std::fabs(n[2]) ? 0
                  : std::fabs(n[1]) <= std::fabs(n[2])                                    ? 1
                                                                                          : 2;
    double e[3] = {0, 0, 0};
    e[k] = 1;
    double t1[3] = {e[1] * n[2] - e[2] * n[1], e[2] * n[0] - e[0] * n[2], e[0] * n[1] - e[1] * n[0]};
    const double l = std::sqrt(t1[0] * t1[0] + t1[1] * t1[1] + t1[2] * t1[2]);
    for (double& x : t1) x /= l;
    const double t2[3] = {n[1] * t1[2] - n[2] * t1[1], n[2] * t1[0] - n[0] * t1[2], n[0] * t1[1] - n[1] * t1[0]};
    DisplayMesh m;
    // (t1, t2, n) is right-handed: corners in this order turn counter-clockwise seen from +n.
    for (const auto& [a, b] : {std::pair{-1.0, -1.0}, std::pair{1.0, -1.0}, std::pair{1.0, 1.0}, std::pair{-1.0, 1.0}})
      for (int i = 0; i < 3; ++i) m.points.push_back(extent * (a * t1[i] + b * t2[i]));
    m.sizes.push_back(4);
    m.indices = {0, 1, 2, 3};
    return m;
  }

 private:
  std::vector<double> g_;
};
MOREAU_REGISTER(Plane, "plane")
}  // namespace
MOREAU_PLUGIN_LIBRARY("moreau_shape_plane")
