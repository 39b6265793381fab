#pragma once
// A narrow-phase detector for one pair of shape names, registered as "first-second"
// (e.g. "disk-segment", "sphere-plane"). The kernel looks up "a-b", then "b-a" with the
// roles exchanged, so a pair needs one detector. A detector whose second shape is a mesh
// facet (edge, face) may find a candidate against several facets of one body; the kernel
// keeps the nearest (docs/contacts.md, "Meshes").
#include <moreau/plugin.hpp>
#include <moreau/shape.hpp>
#include <vector>

namespace moreau {

/// One contact point between the first and the second shape.
struct ContactPoint {
  double point[3] = {0, 0, 0};   ///< world; on the second shape's surface side, midway in the gap
  double normal[3] = {0, 0, 0};  ///< unit, world, from the second shape toward the first
  double gap = 0;                ///< signed distance (m), negative when overlapping
  int feature = 0;               ///< stable index of this point within the pair (manifolds)
  /// Interpolation weights of the point on the support nodes of the first [0] and second
  /// [1] shape: for a facet shape, the weights of its nodes (Pose::nodes order, summing to
  /// 1); shapes on one node keep {1, 0, 0, 0}.
  double weights[2][4] = {{1, 0, 0, 0}, {1, 0, 0, 0}};
};

class MOREAU_API Detector : public Plugin {
 public:
  static constexpr Kind kind = Kind::detector;
  /// Appends the contact points whose gap is below `alert`.
  virtual void detect(int dim, const Shape& first, const Pose& a, const Shape& second, const Pose& b, double alert,
                      std::vector<ContactPoint>& out) const = 0;
};

}  // namespace moreau
