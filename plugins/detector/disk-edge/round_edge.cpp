// `disk-edge` (LMGC90's DKALp) and `point-edge` (CLALp: a mesh node, radius 0): a round
// shape against one boundary edge of a mesh (shape `edge`, placed by its two nodes in
// Pose::nodes). The test itself: round_edge.hpp.
#include "round_edge.hpp"

namespace {
using namespace moreau;

class RoundEdge : public Detector {
 public:
  static Schema schema() {
    Schema s;
    s.dimensions({2});
    return s;
  }
  static constexpr const char* doc = "a round shape (disk, or a mesh node) against a boundary edge of a mesh";
  RoundEdge(const Params&, const BuildContext&) {}
  void detect(int, const Shape& round, const Pose& a, const Shape&, const Pose& b, double alert,
              std::vector<ContactPoint>& out) const override {
    ContactPoint c;
    if (moreau_mesh_contact::round_edge(a.position, round.geometry()[0], b.nodes, b.nodes + 3, alert, c)) out.push_back(c);
  }
};
MOREAU_REGISTER(RoundEdge, DETECTOR_NAME)
}  // namespace
MOREAU_PLUGIN_LIBRARY("moreau_detector_" DETECTOR_NAME)
