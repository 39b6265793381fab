#include "force_network.hpp"

#include <algorithm>
#include <cmath>
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
  // Each node's reach: the largest of its contactors'. A node of a mesh (a body of several
  // nodes) reaches as far as its body: the radius of its nodes about their mean.
  std::vector<double> reach(nodes.size(), 0.0);
  std::vector<char> on_mesh(nodes.size(), 0);
  auto node_of = [&](std::size_t c) { return nodes.first[contactors[c].model] + contactors[c].node; };
  for (std::size_t c = 0; c < contactors.size(); ++c) reach[node_of(c)] = std::max(reach[node_of(c)], contactors[c].reach);
  for (std::size_t b = 0; b < state.bodies(); ++b) {
    const BodyRows rows = state.body(b);
    if (rows.nodes < 2) continue;
    const std::size_t first = nodes.first[static_cast<std::size_t>(rows.model)] + rows.first_node;
    double mean[3] = {0, 0, 0}, radius = 0;
    for (std::size_t n = first; n < first + rows.nodes; ++n)
      for (int k = 0; k < d; ++k) mean[k] += nodes.position[d * n + k] / static_cast<double>(rows.nodes);
    for (std::size_t n = first; n < first + rows.nodes; ++n) {
      double r2 = 0;
      for (int k = 0; k < d; ++k) r2 += (nodes.position[d * n + k] - mean[k]) * (nodes.position[d * n + k] - mean[k]);
      radius = std::max(radius, std::sqrt(r2));
    }
    for (std::size_t n = first; n < first + rows.nodes; ++n) {
      reach[n] = radius;
      on_mesh[n] = 1;
    }
  }
  const double* key = set.field(C::key).data();
  const double* point = set.field(C::point).data();
  for (std::size_t i = 0; i < nc; ++i) {
    const std::size_t a = node_of(static_cast<std::size_t>(key[3 * i])), b = node_of(static_cast<std::size_t>(key[3 * i + 1]));
    const double* p = point + d * i;
    // Each end is its node's position unless that node is far larger than the other, or
    // one node of a mesh (its contacts would fan out from nodes near them, or from the
    // body's middle): there it is the contact point.
    const double* ends[3] = {!on_mesh[a] && reach[a] <= network_size_ratio * reach[b] ? &nodes.position[d * a] : p, p,
                             !on_mesh[b] && reach[b] <= network_size_ratio * reach[a] ? &nodes.position[d * b] : p};
    float* o = &out[3 * d * i];
    for (int e = 0; e < 3; ++e)
      for (int k = 0; k < d; ++k) o[d * e + k] = static_cast<float>(ends[e][k]);
  }
}

}  // namespace moreau::io
