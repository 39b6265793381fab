// `sphere` (3D): a sphere of `radius` centred on the body origin.
#include <moreau/shape.hpp>
#include <numbers>

namespace {
using namespace moreau;

class Sphere : public Shape {
 public:
  static Schema schema() {
    Schema s;
    s.number("radius", "sphere radius").units("m").gt(0);
    s.dimensions({3});
    return s;
  }
  static constexpr const char* doc = "sphere (3D)";
  Sphere(const Params& p, const BuildContext&) : g_{p.number("radius")} {}
  const char* shape_name() const override { return "sphere"; }
  const std::vector<double>& geometry() const override { return g_; }
  MassProperties mass_properties() const override {
    const double r = g_[0], r5 = r * r * r * r * r;
    MassProperties m;
    m.volume = 4.0 / 3.0 * std::numbers::pi * r * r * r;
    m.inertia[0] = m.inertia[4] = m.inertia[8] = 8.0 / 15.0 * std::numbers::pi * r5;  // (2/5) V r²
    return m;
  }
  void bounds(int, const Pose& p, double lo[3], double hi[3]) const override {
    for (int k = 0; k < 3; ++k) {
      lo[k] = p.position[k] - g_[0];
      hi[k] = p.position[k] + g_[0];
    }
  }

 private:
  std::vector<double> g_;
};
MOREAU_REGISTER(Sphere, "sphere")
}  // namespace
MOREAU_PLUGIN_LIBRARY("moreau_shape_sphere")
