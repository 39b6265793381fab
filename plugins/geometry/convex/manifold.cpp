// Reduction of a contact manifold to 4 points (more add nothing to the support polygon a
// rigid body rests on, and make W singular): the deepest point, the one farthest from it,
// then the two that add the most area on either side of that diagonal.
#include <cmath>

#include "convex.hpp"

namespace moreau::geom {

void reduce_manifold(std::vector<ContactPoint>& pts, std::size_t first) {
  const std::size_t n = pts.size() - first;
  if (n <= 4) return;
  auto P = [&](std::size_t i) { return V3{pts[first + i].point[0], pts[first + i].point[1], pts[first + i].point[2]}; };
  const V3 normal{pts[first].normal[0], pts[first].normal[1], pts[first].normal[2]};
  std::size_t a = 0;
  for (std::size_t i = 1; i < n; ++i)
    if (pts[first + i].gap < pts[first + a].gap) a = i;
  std::size_t b = a;
  double far = -1;
  for (std::size_t i = 0; i < n; ++i)
    if (norm(P(i) - P(a)) > far) {
      far = norm(P(i) - P(a));
      b = i;
    }
  std::size_t c = a, d = a;
  double cmax = 0, dmin = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double s = dot(cross(P(b) - P(a), P(i) - P(a)), normal);  // twice the signed area
    if (s > cmax) cmax = s, c = i;
    if (s < dmin) dmin = s, d = i;
  }
  std::vector<ContactPoint> keep;
  std::vector<std::size_t> kept;
  for (std::size_t i : {a, b, c, d}) {
    bool dup = false;
    for (std::size_t k : kept) dup = dup || k == i;
    if (dup) continue;
    kept.push_back(i);
    keep.push_back(pts[first + i]);
  }
  pts.resize(first);
  pts.insert(pts.end(), keep.begin(), keep.end());
}

}  // namespace moreau::geom
