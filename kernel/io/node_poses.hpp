#pragma once
// The poses of every node of every modelization, numbered model by model (the display
// meshes' `point_node` and the contactors' supports index them): position (node field
// `position`) and rotation (`angle` in 2D, `orientation` in 3D; none: no rotation).
#include <moreau/state.hpp>
#include <vector>

namespace moreau::io {

struct NodePoses {
  std::vector<std::size_t> first;  ///< per model: the number of its first node
  std::vector<double> position;    ///< nodes × d
  std::vector<double> rotation;    ///< nodes × (1 in 2D, 4 in 3D)
  std::size_t size() const { return position.size() / (dim ? dim : 1); }
  int dim = 3;
};

/// Node numbering only (first node of each model), without reading any field.
std::vector<std::size_t> node_numbering(const State& state);
/// The poses at `depth` (frames: Depth::begin, after end_step swapped the depths).
void node_poses(const State& state, Depth depth, NodePoses& out);

}  // namespace moreau::io
