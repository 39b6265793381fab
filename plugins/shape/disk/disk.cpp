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

 private:
  std::vector<double> g_;
};
MOREAU_REGISTER(Disk, "disk")
}  // namespace
MOREAU_PLUGIN_LIBRARY("moreau_shape_disk")
