#pragma once
// The force network a viewer draws (docs/output.md, "Viewer description"): one polyline
// per contact, from the first side's node (a grain's centre) to the contact point to the
// second side's node, so chains read between grain centres and contact points. A node far
// larger than its partner (a wall, a floor, a half-space) would turn its lines into fans
// from its centre: its half of the line ends at the contact point instead. So does the
// half on a mesh (a body of several nodes), whose size is its nodes' radius about their mean.
#include <moreau/state.hpp>
#include <vector>

#include "output_writer.hpp"

namespace moreau::io {

/// A side is "far larger" than the other above this ratio of their nodes' reaches.
inline constexpr double network_size_ratio = 4;

/// The polylines' points of the state's `contacts` set, 3 per contact (first node or the
/// contact point, the contact point, second node or the contact point), d floats each,
/// from the contacts' keys (their contactors, hence nodes), points and the nodes'
/// positions at `depth`. A node's reach is the largest `reach` of its contactors.
void force_network_points(const State& state, const std::vector<ContactorInfo>& contactors, Depth depth,
                          std::vector<float>& out);

}  // namespace moreau::io
