#include "display_build.hpp"

#include <algorithm>
#include <cmath>
#include <moreau/error.hpp>
#include <stdexcept>

#include "../contact/placement.hpp"
#include "../io/node_poses.hpp"

namespace moreau::kernel {

namespace {

/// A contactor's world pose at the start (position 3, rotation 4 as compose_pose lays it),
/// from its node's pose (`n`: its number in the node poses).
std::array<double, 7> start_pose(int d, const double* x, const double* r, std::size_t n, const io::ContactorInfo& c) {
  double body[7] = {0, 0, 0, 0, 0, 0, 0};
  for (int k = 0; k < d; ++k) body[k] = x[d * n + k];
  if (d == 2) body[3] = r[n];
  else for (int k = 0; k < 4; ++k) body[3 + k] = r[4 * n + k];
  Placement p;
  p.offset = c.offset;
  if (d == 2) p.angle = c.rotation[0];
  else p.orientation = c.rotation;
  std::array<double, 7> out{};
  compose_pose(d, body, p, out.data());
  return out;
}

}  // namespace

std::shared_ptr<const io::DisplayMeshes> build_display(const State& state, const std::vector<io::ContactorInfo>& info,
                                                       const std::vector<const Shape*>& shapes) {
  const int d = state.dimension();
  io::NodePoses poses;
  io::node_poses(state, Depth::begin, poses);
  const double* x = poses.position.data();
  const double* r = poses.rotation.data();
  auto node_of = [&](const io::ContactorInfo& c) { return poses.first[c.model] + c.node; };

  // The scene's box at the start: body positions and the bounds of bounded shapes.
  double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
  bool any = false;
  auto grow = [&](const double* a, const double* b) {
    for (int k = 0; k < 3; ++k) {
      lo[k] = any ? std::min(lo[k], a[k]) : a[k];
      hi[k] = any ? std::max(hi[k], b[k]) : b[k];
    }
    any = true;
  };
  for (std::size_t b = 0; b < poses.size(); ++b) {
    const double p[3] = {x[d * b], x[d * b + 1], d == 3 ? x[d * b + 2] : 0.0};
    grow(p, p);
  }
  std::vector<std::array<double, 7>> start;
  for (std::size_t i = 0; i < info.size(); ++i) {
    start.push_back(start_pose(d, x, r, node_of(info[i]), info[i]));
    double a[3], b[3];
    shapes[i]->bounds(d, Pose{start[i].data(), start[i].data() + 3}, a, b);
    if (std::isfinite(a[0] + a[1] + a[2] + b[0] + b[1] + b[2])) grow(a, b);
  }

  auto m = std::make_shared<io::DisplayMeshes>();
  m->dimension = d;
  for (std::size_t i = 0; i < info.size(); ++i) {
    double extent = 0;
    for (int corner = 0; corner < 8; ++corner) {
      double s = 0;
      for (int k = 0; k < 3; ++k) {
        const double e = ((corner >> k) & 1 ? hi[k] : lo[k]) - start[i][k];
        s += e * e;
      }
      extent = std::max(extent, std::sqrt(s));
    }
    if (!(extent > 0)) extent = 1;  // a scene of one point: a 2 m patch rather than none
    try {
      DisplayMesh mesh = shapes[i]->display_mesh(extent);
      if (mesh.empty() && !shapes[i]->has_mass()) continue;  // a mesh's point, edge or face: the mesh is drawn
      io::add_contactor(*m, mesh, info[i].body, static_cast<int>(node_of(info[i])),
                        static_cast<int>(i), info[i].offset.data(),
                        info[i].rotation.data());
    } catch (const std::invalid_argument& e) {
      throw RunError("shape plugin \"" + info[i].shape + "\" (contactor " + std::to_string(i) + "): " + e.what());
    }
  }
  return m;
}

void set_contactor_reach(int d, std::vector<io::ContactorInfo>& info, const std::vector<const Shape*>& shapes) {
  const double zero[4] = {0, 0, 0, 0}, identity[4] = {1, 0, 0, 0};
  for (std::size_t i = 0; i < info.size(); ++i) {
    double lo[3], hi[3];
    shapes[i]->bounds(d, Pose{zero, d == 2 ? zero : identity}, lo, hi);
    double corner = 0, offset = 0;
    for (int k = 0; k < d; ++k) {
      corner += std::max(lo[k] * lo[k], hi[k] * hi[k]);
      offset += info[i].offset[k] * info[i].offset[k];
    }
    info[i].reach = std::sqrt(offset) + std::sqrt(corner);
  }
}

}  // namespace moreau::kernel
