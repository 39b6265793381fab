#pragma once
// A broad phase: from the contactors' bounding boxes, the candidate pairs that may be in
// contact. Never two contactors of one body; only pairs of groups that interact.
#include <cstdint>
#include <moreau/plugin.hpp>
#include <utility>
#include <vector>

namespace moreau {

struct BroadPhaseInput {
  int dim = 3;
  std::vector<double> lo, hi;    ///< per contactor, 3 values each (already grown by the alert distance)
  std::vector<int> body;         ///< per contactor
  std::vector<int> group;        ///< per contactor, index into the interaction table
  int groups = 0;
  std::vector<std::uint8_t> interacts;  ///< groups × groups, symmetric
};

class MOREAU_API BroadPhase : public Plugin {
 public:
  static constexpr Kind kind = Kind::broadphase;
  /// Candidate pairs (i < j), in a deterministic order.
  virtual void pairs(const BroadPhaseInput& in, std::vector<std::pair<int, int>>& out) = 0;
};

}  // namespace moreau
