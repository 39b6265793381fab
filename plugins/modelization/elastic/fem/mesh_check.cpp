#include "mesh_check.hpp"

#include <cmath>
#include <sstream>
#include <vector>

#include "element_geometry.hpp"

namespace moreau::fem {
namespace {

double longest_span(const detail::ElementGeometry& g, int corners) {
  double l2 = 0;
  for (int a = 0; a < corners; ++a)
    for (int b = a + 1; b < corners; ++b) l2 = std::max(l2, (g.X.row(a) - g.X.row(b)).squaredNorm());
  return std::sqrt(l2);
}

}  // namespace

void check_mesh(const Mesh& mesh) {
  const std::string file = mesh.from_file ? mesh.source : "";
  for (int n = 0; n < mesh.node_count(); ++n)
    if (!mesh.x.col(n).allFinite())
      throw MeshError("node " + std::to_string(mesh.node_label(n)) + " of " +
                          (mesh.source.empty() ? std::string("the mesh") : mesh.source) +
                          " has a non-finite coordinate",
                      file);
  if (mesh.dim != 2 && mesh.dim != 3)
    throw MeshError((mesh.source.empty() ? std::string("mesh") : mesh.source) + ": dimension " + std::to_string(mesh.dim) +
                        " (expected 2 or 3)",
                    file);
  std::vector<char> used(mesh.node_count(), 0);
  for (int e = 0; e < mesh.element_count(); ++e) {
    const ElementInfo& info = element_info(mesh.elements.type[e]);
    const auto cell = mesh.elements[e];
    if (info.dim != mesh.dim || static_cast<int>(cell.size()) != info.nodes)
      throw MeshError(mesh.describe_element(e) + " is a " + std::string(info.name) + " with " +
                          std::to_string(cell.size()) + " nodes in a " + std::to_string(mesh.dim) + "D mesh",
                      file, mesh.element_line.empty() ? 0 : mesh.element_line[e], mesh.element_label(e));
    for (int n : cell) {
      if (n < 0 || n >= mesh.node_count())
        throw MeshError(mesh.describe_element(e) + " refers to node index " + std::to_string(n) + ", outside [0, " +
                            std::to_string(mesh.node_count()) + ")",
                        file, mesh.element_line.empty() ? 0 : mesh.element_line[e], mesh.element_label(e));
      used[n] = 1;
    }
  }
  for (int n = 0; n < mesh.node_count(); ++n)
    if (!used[n])
      throw MeshError("node " + std::to_string(mesh.node_label(n)) + " of " +
                          (mesh.source.empty() ? std::string("the mesh") : mesh.source) +
                          " belongs to no element (it would be free to move with no stiffness)",
                      file);
  std::ostringstream faults;
  int count = 0, first = -1;
  detail::ElementGeometry g;
  for (int e = 0; e < mesh.element_count(); ++e) {
    g.bind(mesh, e);
    const ElementInfo& info = element_info(g.type);
    const double scale = std::pow(longest_span(g, info.corners), mesh.dim);
    const int points = static_cast<int>(info.rule.size());
    for (int q = 0; q < points; ++q) {
      const double det = g.evaluate(info.rule[q].xi.data());
      const bool inverted = det < 0, degenerate = !(std::abs(det) > degenerate_tolerance * scale);
      if (!inverted && !degenerate) continue;
      if (count < 10)
        faults << "\n  " << mesh.describe_element(e) << " (" << info.name << ") is "
               << (degenerate ? "degenerate" : "inverted") << ": Jacobian determinant " << det
               << " at integration point " << q + 1 << " of " << points;
      if (first < 0) first = e;
      ++count;
      break;
    }
  }
  if (count == 0) return;
  if (count > 10) faults << "\n  … and " << count - 10 << " more";
  const long line = mesh.element_line.empty() ? 0 : mesh.element_line[first];
  throw MeshError((mesh.source.empty() ? std::string("mesh") : mesh.source) + ": " + std::to_string(count) +
                      " inverted or degenerate element" + (count > 1 ? "s" : "") + faults.str(),
                  file, line, mesh.element_label(first));
}

}  // namespace moreau::fem
