// `point` (2D and 3D): a node of a mesh as a contact candidate (LMGC90's CLxxx in 2D,
// CSxxx in 3D). It is a round shape of radius 0 (geometry {0}), so every detector written
// for a disk or a sphere against something takes it as is: `point-disk`, `point-plane`…
// are those detectors registered again. No mass (the body's mass is its material's), no
// drawing (the mesh is drawn). Usually placed on every node of a boundary group
// (contactor key `boundary`, docs/scene.md).
#include <moreau/shape.hpp>

namespace {
using namespace moreau;

class Point : public Shape {
 public:
  static Schema schema() { return {}; }
  static constexpr const char* doc = "a node of a mesh as a contact candidate (radius 0)";
  Point(const Params&, const BuildContext&) {}
  const char* shape_name() const override { return "point"; }
  const std::vector<double>& geometry() const override { return g_; }
  bool has_mass() const override { return false; }
  MassProperties mass_properties() const override { return {}; }
  void bounds(int dim, const Pose& p, double lo[3], double hi[3]) const override {
    for (int k = 0; k < 3; ++k) lo[k] = hi[k] = k < dim ? p.position[k] : 0.0;
  }

 private:
  std::vector<double> g_{0.0};
};
MOREAU_REGISTER(Point, "point")
}  // namespace
MOREAU_PLUGIN_LIBRARY("moreau_shape_point")
