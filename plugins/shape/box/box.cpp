// `box` (3D): a rectangular box of full edge lengths `size` = [lx, ly, lz] along the body
// axes, centred on the body origin.
#include <algorithm>
#include <convex.hpp>
#include <display.hpp>
#include <moreau/shape.hpp>

namespace {
using namespace moreau;

class Box : public Shape {
 public:
  static Schema schema() {
    Schema s;
    s.vector("size", "edge lengths [lx, ly, lz] along the body axes", 3).units("m");
    s.dimensions({3});
    return s;
  }
  static constexpr const char* doc = "rectangular box (3D)";
  Box(const Params& p, const BuildContext&) : g_(p.vector("size")) {
    for (int k = 0; k < 3; ++k)
      if (!(g_[k] > 0)) throw p.error("size", "degenerate box: every edge length must be > 0, got " + std::to_string(g_[k]));
  }
  const char* shape_name() const override { return "box"; }
  const std::vector<double>& geometry() const override { return g_; }
  MassProperties mass_properties() const override {
    const double x = g_[0], y = g_[1], z = g_[2];
    MassProperties m;
    m.volume = x * y * z;
    m.inertia[0] = m.volume * (y * y + z * z) / 12;
    m.inertia[4] = m.volume * (x * x + z * z) / 12;
    m.inertia[8] = m.volume * (x * x + y * y) / 12;
    return m;
  }
  void bounds(int, const Pose& p, double lo[3], double hi[3]) const override {
    // Extent along world axis k: Σ_j |R_kj| l_j / 2.
    for (int k = 0; k < 3; ++k) {
      double e = 0;
      for (int j = 0; j < 3; ++j) {
        geom::V3 a{};
        (j == 0 ? a.x : j == 1 ? a.y : a.z) = g_[j] / 2;
        const geom::V3 r = geom::rotate(p.rotation, a);
        e += std::fabs(k == 0 ? r.x : k == 1 ? r.y : r.z);
      }
      lo[k] = p.position[k] - e;
      hi[k] = p.position[k] + e;
    }
  }
  /// The 8 corners and 6 faces, as the detectors see the box.
  DisplayMesh display_mesh(double) const override { return geom::polyhedron_display(geom::box_geometry_as_convex(g_)); }

 private:
  std::vector<double> g_;
};
MOREAU_REGISTER(Box, "box")
}  // namespace
MOREAU_PLUGIN_LIBRARY("moreau_shape_box")
