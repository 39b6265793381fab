#pragma once
// Display meshes (Shape::display_mesh) of the convex shapes: a polyhedron drawn as its
// hull faces, a polygon as its outline. Kept inline so shapes that only draw need not
// link more of the geometry library.
#include <moreau/shape.hpp>
#include <vector>

namespace moreau::geom {

/// A polyhedron in the `convex` geometry layout {nv, x0, y0, z0, …, nf, k0, i…, …}: its
/// faces (already counter-clockwise from outside) are the display polygons.
inline DisplayMesh polyhedron_display(const std::vector<double>& g) {
  DisplayMesh m;
  const int nv = static_cast<int>(g[0]);
  m.points.assign(g.begin() + 1, g.begin() + 1 + 3 * nv);
  std::size_t at = 1 + 3 * static_cast<std::size_t>(nv);
  const int nf = static_cast<int>(g[at++]);
  for (int f = 0; f < nf; ++f) {
    const int k = static_cast<int>(g[at++]);
    m.sizes.push_back(k);
    for (int i = 0; i < k; ++i) m.indices.push_back(static_cast<int>(g[at++]));
  }
  return m;
}

/// A 2D outline through (x, y) pairs, counter-clockwise: one polygon in the plane z = 0.
inline DisplayMesh outline_display(const std::vector<double>& xy) {
  DisplayMesh m;
  const int n = static_cast<int>(xy.size() / 2);
  for (int i = 0; i < n; ++i) m.points.insert(m.points.end(), {xy[2 * i], xy[2 * i + 1], 0.0});
  m.sizes.push_back(n);
  for (int i = 0; i < n; ++i) m.indices.push_back(i);
  return m;
}

}  // namespace moreau::geom
