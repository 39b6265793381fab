// `segment` (2D): a rounded segment (LMGC90's JONCx) of `length` along the body x axis
// and `thickness` (its ends are half disks): walls and floors.
#include <algorithm>
#include <cmath>
#include <moreau/shape.hpp>
#include <numbers>

namespace {
using namespace moreau;

class Segment : public Shape {
 public:
  static Schema schema() {
    Schema s;
    s.number("length", "length of the core segment (without the rounded ends)").units("m").min(0);
    s.number("thickness", "thickness (twice the rounding radius)").units("m").gt(0);
    s.dimensions({2});
    return s;
  }
  static constexpr const char* doc = "rounded segment (2D walls)";
  Segment(const Params& p, const BuildContext&) : g_{p.number("length"), p.number("thickness")} {}
  const char* shape_name() const override { return "segment"; }
  const std::vector<double>& geometry() const override { return g_; }
  MassProperties mass_properties() const override {
    const double L = g_[0], r = g_[1] / 2, pi = std::numbers::pi;
    MassProperties m;
    const double rect = L * 2 * r, half = pi * r * r / 2;
    m.volume = rect + 2 * half;
    // Rectangle about its centre, plus two half disks moved from their centroids.
    const double c = 4 * r / (3 * pi);  // half-disk centroid from its flat side
    const double half_centroid = pi * r * r * r * r / 4 - half * c * c;
    m.inertia[8] = rect * (L * L + 4 * r * r) / 12 + 2 * (half_centroid + half * (L / 2 + c) * (L / 2 + c));
    return m;
  }
  void bounds(int, const Pose& p, double lo[3], double hi[3]) const override {
    const double hx = g_[0] / 2 * std::cos(p.rotation[0]), hy = g_[0] / 2 * std::sin(p.rotation[0]), r = g_[1] / 2;
    lo[0] = p.position[0] - std::fabs(hx) - r;
    hi[0] = p.position[0] + std::fabs(hx) + r;
    lo[1] = p.position[1] - std::fabs(hy) - r;
    hi[1] = p.position[1] + std::fabs(hy) + r;
    lo[2] = hi[2] = 0;
  }
  /// The stadium outline: the right half circle, then the left one (12 steps each),
  /// counter-clockwise; the straight sides join them.
  DisplayMesh display_mesh(double) const override {
    constexpr int steps = 12;
    const double h = g_[0] / 2, r = g_[1] / 2, pi = std::numbers::pi;
    DisplayMesh m;
    for (int side = 0; side < 2; ++side) {
      const double cx = side == 0 ? h : -h;
      // A zero-length segment (a disk): the arcs meet, so each stops before the other's start.
      const int last = h > 0 ? steps : steps - 1;
      for (int i = 0; i <= last; ++i) {
        const double a = -pi / 2 + pi * side + pi * i / steps;
        m.points.insert(m.points.end(), {cx + r * std::cos(a), r * std::sin(a), 0.0});
      }
    }
    const int n = static_cast<int>(m.points.size() / 3);
    for (int i = 0; i < n; ++i) m.indices.push_back(i);
    m.sizes.push_back(n);
    return m;
  }

 private:
  std::vector<double> g_;
};
MOREAU_REGISTER(Segment, "segment")
}  // namespace
MOREAU_PLUGIN_LIBRARY("moreau_shape_segment")
