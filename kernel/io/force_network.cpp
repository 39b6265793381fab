#include "force_network.hpp"

#include <algorithm>
#include <moreau/contact_fields.hpp>

#include "node_poses.hpp"

namespace moreau::io {

namespace C = moreau::contact_fields;

void force_network_points(const State& state, const std::vector<ContactorInfo>& contactors, Depth depth,
                          std::vector<float>& out) {
  const int d = state.dimension();
  const EntitySet& set = state.set(sets::contacts);
  const std::size_t nc = set.rows();
  out.resize(nc * 3 * static_cast<std::size_t>(d));
  if (nc == 0) return;
  NodePoses nodes;
  node_poses(state, depth, nodes);
  // Each node's reach: the largest of its contactors'.
  std::vector<double> reach(nodes.size(), 0.0);
  auto node_of = [&](std::size_t c) { return nodes.first[contactors[c].model] + contactors[c].node; };
  for (std::size_t c = 0; c < contactors.size(); ++c) reach[node_of(c)] = std::max(reach[node_of(c)], contactors[c].reach);
  const double* key = set.field(C::key).data();
  const double* point = set.field(C::point).data();
  for (std::size_t i = 0; i < nc; ++i) {
    const std::size_t a = node_of(static_cast<std::size_t>(key[3 * i])), b = node_of(static_cast<std::size_t>(key[3 * i + 1]));
    const double* p = point + d * i;
    // Each end is its node's position unless that node is far larger than the other.
    const double* ends[3] = {reach[a] <= network_size_ratio * reach[b] ? &nodes.position[d * a] : p, p,
                             reach[b] <= network_size_ratio * reach[a] ? &nodes.position[d * b] : p};
    float* o = &out[3 * d * i];
    for (int e = 0; e < 3; ++e)
      for (int k = 0; k < d; ++k) o[d * e + k] = static_cast<float>(ends[e][k]);
  }
}

}  // namespace moreau::io
