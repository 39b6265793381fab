// `disk` (2D): a disk of `radius` centred on the body origin.
#include <cmath>
#include <moreau/shape.hpp>
#include <numbers>

namespace {
using namespace moreau;

class Disk : public Shape {
 public:
  static Schema schema() {
    Schema s;
    s.number("radius", "disk radius").units("m").gt(0);
    s.dimensions({2});
    return s;
  }
  static constexpr const char* doc = "disk (2D)";
  Disk(const Params& p, const BuildContext&) : g_{p.number("radius")} {}
  const char* shape_name() const override { return "disk"; }
  const std::vector<double>& geometry() const override { return g_; }
  MassProperties mass_properties() const override {
    const double r = g_[0];
    MassProperties m;
    m.volume = std::numbers::pi * r * r;
    m.inertia[8] = std::numbers::pi * r * r * r * r / 2;  // polar, per unit density and thickness
    return m;
  }
  void bounds(int, const Pose& p, double lo[3], double hi[3]) const override {
    for (int k = 0; k < 2; ++k) {
      lo[k] = p.position[k] - g_[0];
      hi[k] = p.position[k] + g_[0];
    }
    lo[2] = hi[2] = 0;
  }
  /// A regular 24-gon with its vertices on the circle (the first on the body x axis, so
  /// the drawing shows the disk's rotation).
  DisplayMesh display_mesh(double) const override {
    constexpr int n = 24;
    DisplayMesh m;
    for (int i = 0; i < n; ++i) {
      const double a = 2 * std::numbers::pi * i / n;
      m.points.insert(m.points.end(), {g_[0] * std::cos(a), g_[0] * std::sin(a), 0.0});
      m.indices.push_back(i);
    }
    m.sizes.push_back(n);
    return m;
  }

 private:
  std::vector<double> g_;
};
MOREAU_REGISTER(Disk, "disk")
}  // namespace
MOREAU_PLUGIN_LIBRARY("moreau_shape_disk")
