// Convex hull faces of a small point set (the vertices of a `convex` shape), by testing
// every plane through three points: O(n⁴), done once per shape at build time, which is
// why `convex` shapes are limited to a few dozen vertices.
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "convex.hpp"

namespace moreau::geom {

std::vector<std::vector<int>> hull_faces(const std::vector<V3>& p) {
  const int n = static_cast<int>(p.size());
  if (n < 4) throw std::invalid_argument("a convex shape needs at least 4 vertices");
  double scale = 0;
  for (const V3& x : p) scale = std::max(scale, norm(x - p[0]));
  if (scale <= 0) throw std::invalid_argument("all vertices are the same point");
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      if (norm(p[i] - p[j]) <= 1e-9 * scale) throw std::invalid_argument("vertices " + std::to_string(i) + " and " + std::to_string(j) + " are the same point");
  const double tol = 1e-9 * scale;
  std::vector<std::vector<int>> faces;
  std::vector<V3> normals;
  std::vector<char> on_hull(n, 0);
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      for (int k = j + 1; k < n; ++k) {
        V3 nn = cross(p[j] - p[i], p[k] - p[i]);
        const double l = norm(nn);
        if (l <= tol * scale) continue;  // collinear triple
        nn = (1 / l) * nn;
        int above = 0, below = 0;
        for (int m = 0; m < n; ++m) {
          const double s = dot(nn, p[m] - p[i]);
          if (s > tol) ++above;
          else if (s < -tol) ++below;
        }
        if (above && below) continue;
        if (above) nn = -nn;  // outward: every point below
        bool known = false;
        for (const V3& m : normals) known = known || dot(m, nn) > 1 - 1e-9;
        if (known) continue;
        // The face: every point on the plane, ordered counter-clockwise around nn.
        std::vector<int> f;
        V3 c{};
        for (int m = 0; m < n; ++m)
          if (std::fabs(dot(nn, p[m] - p[i])) <= tol) {
            f.push_back(m);
            c = c + p[m];
          }
        c = (1.0 / f.size()) * c;
        const V3 u = (1 / norm(p[f[0]] - c)) * (p[f[0]] - c), w = cross(nn, u);
        std::sort(f.begin(), f.end(), [&](int a, int b) {
          return std::atan2(dot(p[a] - c, w), dot(p[a] - c, u)) < std::atan2(dot(p[b] - c, w), dot(p[b] - c, u));
        });
        // A point strictly inside a face's edge or polygon is not a vertex.
        for (std::size_t m = 0; m < f.size(); ++m) {
          const V3 a = p[f[(m + f.size() - 1) % f.size()]], b = p[f[m]], d = p[f[(m + 1) % f.size()]];
          if (norm(cross(b - a, d - b)) <= tol * scale)
            throw std::invalid_argument("vertex " + std::to_string(f[m]) + " is not a corner of the hull");
        }
        for (int m : f) on_hull[m] = 1;
        normals.push_back(nn);
        faces.push_back(f);
      }
  if (faces.size() < 4) throw std::invalid_argument("the vertices are coplanar (no volume)");
  for (int m = 0; m < n; ++m)
    if (!on_hull[m]) throw std::invalid_argument("vertex " + std::to_string(m) + " is inside the hull (list only the corners)");
  return faces;
}

}  // namespace moreau::geom
