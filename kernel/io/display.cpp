#include "display.hpp"

#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

namespace moreau::io {

namespace {

/// Row-major rotation matrix of a 2D angle (about z) or a 3D unit quaternion w x y z.
std::array<double, 9> rotation_matrix(int dim, const double* r) {
  if (dim == 2) {
    const double c = std::cos(r[0]), s = std::sin(r[0]);
    return {c, -s, 0, s, c, 0, 0, 0, 1};
  }
  const double w = r[0], x = r[1], y = r[2], z = r[3];
  return {1 - 2 * (y * y + z * z), 2 * (x * y - w * z),     2 * (x * z + w * y),
          2 * (x * y + w * z),     1 - 2 * (x * x + z * z), 2 * (y * z - w * x),
          2 * (x * z - w * y),     2 * (y * z + w * x),     1 - 2 * (x * x + y * y)};
}

}  // namespace

void add_contactor(DisplayMeshes& m, const DisplayMesh& mesh, int body, int node, int contactor, const double offset[3],
                   const double rotation[4]) {
  const int first = static_cast<int>(m.vertices());
  if (mesh.empty()) {
    m.points.insert(m.points.end(), {offset[0], offset[1], m.dimension == 2 ? 0.0 : offset[2]});
    m.point_body.push_back(body);
    m.point_node.push_back(node);
    m.cells.insert(m.cells.end(), {xdmf_polyvertex, 1, first});
    m.cell_body.push_back(body);
    m.cell_contactor.push_back(contactor);
    return;
  }
  const auto R = rotation_matrix(m.dimension, rotation);
  const std::size_t nv = mesh.points.size() / 3;
  for (std::size_t v = 0; v < nv; ++v) {
    const double* s = &mesh.points[3 * v];
    for (int i = 0; i < 3; ++i)
      m.points.push_back(offset[i] + R[3 * i] * s[0] + R[3 * i + 1] * s[1] + R[3 * i + 2] * s[2]);
    if (m.dimension == 2) m.points.back() = 0;
    m.point_body.push_back(body);
    m.point_node.push_back(node);
  }
  std::size_t at = 0;
  for (const int k : mesh.sizes) {
    if (k < 3 || at + k > mesh.indices.size())
      throw std::invalid_argument("display mesh: polygon " + std::to_string(m.cell_count()) + " has " +
                                  std::to_string(k) + " vertices or runs past the index list");
    if (k == 3) m.cells.push_back(xdmf_triangle);
    else if (k == 4) m.cells.push_back(xdmf_quadrilateral);
    else m.cells.insert(m.cells.end(), {xdmf_polygon, k});
    for (int i = 0; i < k; ++i) {
      const int v = mesh.indices[at++];
      if (v < 0 || static_cast<std::size_t>(v) >= nv)
        throw std::invalid_argument("display mesh: vertex index " + std::to_string(v) + " out of " +
                                    std::to_string(nv) + " vertices");
      m.cells.push_back(first + v);
    }
    m.cell_body.push_back(body);
    m.cell_contactor.push_back(contactor);
  }
}

void world_points(const DisplayMeshes& m, std::size_t nodes, const double* position, const double* rotation,
                  std::vector<float>& out) {
  const int d = m.dimension, nr = d == 2 ? 1 : 4;
  std::vector<std::array<double, 9>> R(nodes);  // once per node, not per vertex
  for (std::size_t b = 0; b < nodes; ++b) R[b] = rotation_matrix(d, rotation + nr * b);
  const std::size_t nv = m.vertices();
  out.resize(nv * d);
  for (std::size_t v = 0; v < nv; ++v) {
    const std::size_t b = static_cast<std::size_t>(m.point_node[v]);
    const double* p = &m.points[3 * v];
    const auto& r = R[b];
    for (int i = 0; i < d; ++i)
      out[d * v + i] = static_cast<float>(position[d * b + i] + r[3 * i] * p[0] + r[3 * i + 1] * p[1] + r[3 * i + 2] * p[2]);
  }
}

}  // namespace moreau::io
