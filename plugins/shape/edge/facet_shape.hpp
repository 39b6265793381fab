#pragma once
// The facet shapes `edge` (2D) and `face` (3D): a boundary facet of a mesh as a contact
// antagonist (LMGC90's ALpxx / ASpxx), supported by the facet's nodes (Support::facet):
// the kernel gives their positions in Pose::nodes, so the shape itself holds nothing. No
// mass, no drawing (the mesh is drawn).
#include <algorithm>
#include <moreau/shape.hpp>

namespace moreau_facet {

using namespace moreau;

template <int Dim>
class Facet : public Shape {
 public:
  static Schema schema() {
    Schema s;
    s.dimensions({Dim});
    return s;
  }
  Facet(const Params&, const BuildContext&) {}
  const char* shape_name() const override { return Dim == 2 ? "edge" : "face"; }
  const std::vector<double>& geometry() const override { return g_; }
  bool has_mass() const override { return false; }
  Support support() const override { return Support::facet; }
  MassProperties mass_properties() const override { return {}; }
  /// The box of its nodes (before they are known: the point it is placed at).
  void bounds(int dim, const Pose& p, double lo[3], double hi[3]) const override {
    for (int k = 0; k < 3; ++k) lo[k] = hi[k] = k < dim ? p.position[k] : 0.0;
    for (int j = 0; j < p.node_count; ++j)
      for (int k = 0; k < dim; ++k) {
        lo[k] = std::min(lo[k], p.nodes[3 * j + k]);
        hi[k] = std::max(hi[k], p.nodes[3 * j + k]);
      }
  }

 private:
  std::vector<double> g_;
};

}  // namespace moreau_facet
