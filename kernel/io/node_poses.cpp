#include "node_poses.hpp"

#include <algorithm>
#include <moreau/node_fields.hpp>

namespace moreau::io {

std::vector<std::size_t> node_numbering(const State& st) {
  std::vector<std::size_t> first;
  std::size_t n = 0;
  for (const auto& m : st.models()) {
    first.push_back(n);
    n += st.set(m.nodes).rows();
  }
  return first;
}

void node_poses(const State& st, Depth depth, NodePoses& out) {
  const int d = st.dimension(), nr = d == 2 ? 1 : 4;
  out.dim = d;
  out.first = node_numbering(st);
  std::size_t total = 0;
  for (const auto& m : st.models()) total += st.set(m.nodes).rows();
  out.position.assign(total * d, 0.0);
  out.rotation.assign(total * nr, 0.0);
  for (std::size_t mi = 0; mi < st.models().size(); ++mi) {
    const EntitySet& set = st.set(st.models()[mi].nodes);
    const std::size_t n = set.rows(), at = out.first[mi];
    if (const Field* x = set.find(node_fields::position))
      std::copy(x->data(depth), x->data(depth) + n * d, &out.position[at * d]);
    if (const Field* q = set.find(d == 2 ? node_fields::angle : node_fields::orientation)) {
      std::copy(q->data(depth), q->data(depth) + n * nr, &out.rotation[at * nr]);
    } else if (d == 3) {
      for (std::size_t i = 0; i < n; ++i) out.rotation[(at + i) * 4] = 1;
    }
  }
}

}  // namespace moreau::io
