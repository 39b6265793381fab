// `sphere-face` and `point-face` (LMGC90's CSASp: a mesh node, radius 0): a round shape
// against one boundary face of a mesh (shape `face`, placed by its 3 or 4 nodes in
// Pose::nodes, counter-clockwise seen from outside). The test itself: round_face.hpp.
#include "round_face.hpp"

namespace {
using namespace moreau;

class RoundFace : public Detector {
 public:
  static Schema schema() {
    Schema s;
    s.dimensions({3});
    return s;
  }
  static constexpr const char* doc = "a round shape (sphere, or a mesh node) against a boundary face of a mesh";
  RoundFace(const Params&, const BuildContext&) {}
  void detect(int, const Shape& round, const Pose& a, const Shape&, const Pose& b, double alert,
              std::vector<ContactPoint>& out) const override {
    ContactPoint c;
    if (moreau_mesh_contact::round_face(a.position, round.geometry()[0], b.nodes, b.node_count, alert, c)) out.push_back(c);
  }
};
MOREAU_REGISTER(RoundFace, DETECTOR_NAME)
}  // namespace
MOREAU_PLUGIN_LIBRARY("moreau_detector_" DETECTOR_NAME)
