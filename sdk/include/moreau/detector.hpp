#pragma once
// A narrow-phase detector for one pair of shape names, registered as "first-second"
// (e.g. "disk-segment", "sphere-plane"). The kernel looks up "a-b", then "b-a" with the
// roles exchanged, so a pair needs one detector.
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
};

class MOREAU_API Detector : public Plugin {
 public:
  static constexpr Kind kind = Kind::detector;
  /// Appends the contact points whose gap is below `alert`.
  virtual void detect(int dim, const Shape& first, const Pose& a, const Shape& second, const Pose& b, double alert,
                      std::vector<ContactPoint>& out) const = 0;
};

}  // namespace moreau
