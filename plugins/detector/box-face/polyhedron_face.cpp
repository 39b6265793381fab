// `box-face` and `convex-face` (LMGC90's PRASp): the corners of a rigid box or convex
// polyhedron as candidates against one boundary face of a mesh (shape `face`). Each corner
// is a point (radius 0) tested as `point-face` tests a mesh node (round_face.hpp); its
// index is the contact's feature, so the kernel keeps, per corner and mesh body, the
// nearest face (docs/contacts.md, "Meshes"). Mesh nodes against the shape's faces are the
// other direction, `point-box` / `point-convex`: pair both for a two-way treatment
// (docs/scene.md, "Contactors on meshes"). Edges crossing edges are not tested (as PRASp).
#include <convex.hpp>

#include "../sphere-face/round_face.hpp"

namespace {
using namespace moreau;

class PolyhedronFace : public Detector {
 public:
  static Schema schema() {
    Schema s;
    s.dimensions({3});
    return s;
  }
  static constexpr const char* doc = "the corners of a box or convex shape against a boundary face of a mesh";
  PolyhedronFace(const Params&, const BuildContext&) {}
  void detect(int, const Shape& shape, const Pose& a, const Shape&, const Pose& b, double alert,
              std::vector<ContactPoint>& out) const override {
    const geom::Polyhedron p = geom::polyhedron_at(shape.shape_name(), shape.geometry(), a);
    for (std::size_t i = 0; i < p.v.size(); ++i) {
      const double corner[3] = {p.v[i].x, p.v[i].y, p.v[i].z};
      ContactPoint c;
      c.feature = static_cast<int>(i);
      if (moreau_mesh_contact::round_face(corner, 0.0, b.nodes, b.node_count, alert, c)) out.push_back(c);
    }
  }
};
MOREAU_REGISTER(PolyhedronFace, DETECTOR_NAME)
}  // namespace
MOREAU_PLUGIN_LIBRARY("moreau_detector_" DETECTOR_NAME)
