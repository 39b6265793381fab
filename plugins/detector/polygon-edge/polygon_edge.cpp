// `polygon-edge` (LMGC90's PLALp): the corners of a rigid polygon as candidates against
// one boundary edge of a mesh (shape `edge`). Each corner is a point (radius 0) tested as
// `point-edge` tests a mesh node (round_edge.hpp); its index is the contact's feature, so
// the kernel keeps, per corner and mesh body, the nearest edge (docs/contacts.md,
// "Meshes"). A mesh node against the polygon's sides is the other direction, `point-polygon`:
// pair both for a two-way treatment (docs/scene.md, "Contactors on meshes").
#include <convex.hpp>

#include "../disk-edge/round_edge.hpp"

namespace {
using namespace moreau;

class PolygonEdge : public Detector {
 public:
  static Schema schema() {
    Schema s;
    s.dimensions({2});
    return s;
  }
  static constexpr const char* doc = "the corners of a polygon against a boundary edge of a mesh";
  PolygonEdge(const Params&, const BuildContext&) {}
  void detect(int, const Shape& polygon, const Pose& a, const Shape&, const Pose& b, double alert,
              std::vector<ContactPoint>& out) const override {
    const geom::Polygon p = geom::polygon_at(polygon.geometry(), a);
    for (std::size_t i = 0; i < p.v.size(); ++i) {
      const double corner[2] = {p.v[i].x, p.v[i].y};
      ContactPoint c;
      c.feature = static_cast<int>(i);
      if (moreau_mesh_contact::round_edge(corner, 0.0, b.nodes, b.nodes + 3, alert, c)) out.push_back(c);
    }
  }
};
MOREAU_REGISTER(PolygonEdge, "polygon-edge")
}  // namespace
MOREAU_PLUGIN_LIBRARY("moreau_detector_polygon-edge")
