// Convex polygons: validation, mass properties, and contacts by separating axes with
// clipping of the incident edge against the reference edge (2 points for a face contact).
#include <algorithm>
#include <limits>
#include <stdexcept>

#include "convex.hpp"

namespace moreau::geom {

std::vector<V2> convex_polygon(const std::vector<std::array<double, 2>>& in) {
  if (in.size() < 3) throw std::invalid_argument("a polygon needs at least 3 vertices");
  std::vector<V2> v;
  for (const auto& p : in) v.push_back({p[0], p[1]});
  double area2 = 0, scale = 0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    area2 += cross(v[i], v[(i + 1) % v.size()]);
    scale = std::max(scale, norm(v[i] - v[0]));
  }
  if (area2 < 0) std::reverse(v.begin(), v.end());  // clockwise given: turn it
  const std::size_t n = v.size();
  for (std::size_t i = 0; i < n; ++i) {
    const V2 e0 = v[(i + 1) % n] - v[i], e1 = v[(i + 2) % n] - v[(i + 1) % n];
    if (norm(e0) <= 1e-12 * std::max(scale, 1e-300)) throw std::invalid_argument("repeated vertex " + std::to_string(i));
    const double turn = cross(e0, e1) / (norm(e0) * norm(e1));
    if (std::fabs(turn) <= 1e-9) throw std::invalid_argument("collinear vertices around vertex " + std::to_string((i + 1) % n));
    if (turn < 0) throw std::invalid_argument("not convex at vertex " + std::to_string((i + 1) % n) + " (or the vertices are not in order around the polygon)");
  }
  return v;
}

double polygon_half_width(const std::vector<V2>& v) {
  double w = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < v.size(); ++i) {
    const V2 a = v[i], e = v[(i + 1) % v.size()] - a;
    double across = 0;
    for (const V2& q : v) across = std::max(across, std::fabs(cross(e, q - a)));
    w = std::min(w, across / norm(e));
  }
  return w / 2;
}

MassProperties polygon_mass(const std::vector<V2>& v) {
  MassProperties m;
  double A = 0, cx = 0, cy = 0, J = 0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const V2 a = v[i], b = v[(i + 1) % v.size()];
    const double c = cross(a, b);
    A += c / 2;
    cx += (a.x + b.x) * c / 6;
    cy += (a.y + b.y) * c / 6;
    J += c * (a.x * a.x + a.x * b.x + b.x * b.x + a.y * a.y + a.y * b.y + b.y * b.y) / 12;
  }
  m.volume = A;
  m.center = {cx / A, cy / A, 0};
  m.inertia[8] = J - A * (m.center[0] * m.center[0] + m.center[1] * m.center[1]);  // about the centroid
  return m;
}

Polygon polygon_at(const std::vector<double>& g, const Pose& p) {
  Polygon poly;
  const int n = static_cast<int>(g[0]);
  const V2 x{p.position[0], p.position[1]};
  for (int i = 0; i < n; ++i) poly.v.push_back(x + rotate(p.rotation[0], V2{g[1 + 2 * i], g[2 + 2 * i]}));
  return poly;
}

Polygon segment_at(const std::vector<double>& g, const Pose& p) {
  const V2 x{p.position[0], p.position[1]};
  const V2 e = rotate(p.rotation[0], V2{g[0] / 2, 0});
  return Polygon{{x - e, x + e}, g[1] / 2};
}

namespace {

V2 edge_normal(const Polygon& p, std::size_t i) {
  const V2 e = p.v[(i + 1) % p.v.size()] - p.v[i];
  const double l = norm(e);
  return {e.y / l, -e.x / l};  // outward for counter-clockwise vertices
}

/// Largest separation of q's core from p's edges: max over edges of min over q's vertices.
double max_separation(const Polygon& p, const Polygon& q, std::size_t& best) {
  double s_best = -std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < p.v.size(); ++i) {
    const V2 n = edge_normal(p, i);
    double s = std::numeric_limits<double>::infinity();
    for (const V2& w : q.v) s = std::min(s, dot(n, w - p.v[i]));
    if (s > s_best) {
      s_best = s;
      best = i;
    }
  }
  return s_best;
}

}  // namespace

void polygon_polygon(const Polygon& a, const Polygon& b, double alert, std::vector<ContactPoint>& out) {
  std::size_t ia = 0, ib = 0;
  const double sa = max_separation(a, b, ia), sb = max_separation(b, a, ib);
  const double radii = a.radius + b.radius;
  if (std::max(sa, sb) - radii > alert) return;
  // Reference edge: b's unless a's separates clearly better (a slight bias keeps the
  // choice, hence the contact identities, from flickering between equal candidates).
  const bool ref_is_b = sb >= sa - 1e-9 * (1 + std::fabs(sa));
  const Polygon& ref = ref_is_b ? b : a;
  const Polygon& inc = ref_is_b ? a : b;
  const std::size_t r = ref_is_b ? ib : ia;
  const V2 n = edge_normal(ref, r);
  // Incident edge: the one of `inc` most opposed to n.
  std::size_t k = 0;
  double lowest = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < inc.v.size(); ++i) {
    const double c = dot(edge_normal(inc, i), n);
    if (c < lowest) {
      lowest = c;
      k = i;
    }
  }
  // A point keeps the id of the incident vertex it comes from, clipped or not: two equal
  // faces placed flush and sheared (a glued joint) keep their contacts, and with them
  // the warm start and the laws' internal variables (docs/laws.md).
  V2 p[2] = {inc.v[k], inc.v[(k + 1) % inc.v.size()]};
  const int id[2] = {static_cast<int>(k), static_cast<int>((k + 1) % inc.v.size())};
  // Clip to the reference edge's extent.
  const V2 r0 = ref.v[r], r1 = ref.v[(r + 1) % ref.v.size()];
  const V2 t = (1 / norm(r1 - r0)) * (r1 - r0);
  const double lo = 0, hi = dot(r1 - r0, t);
  for (int side = 0; side < 2; ++side) {
    const double s0 = dot(p[0] - r0, t), s1 = dot(p[1] - r0, t);
    const double lim = side == 0 ? lo : hi;
    const bool out0 = side == 0 ? s0 < lim : s0 > lim, out1 = side == 0 ? s1 < lim : s1 > lim;
    if (out0 && out1) return;  // no overlap along the edge (only for rounded corner cases)
    if (out0 || out1) {
      const int o = out0 ? 0 : 1;
      const double f = (lim - s0) / (s1 - s0);
      p[o] = p[0] + f * (p[1] - p[0]);
    }
  }
  const double rr = ref_is_b ? b.radius : a.radius, ri = ref_is_b ? a.radius : b.radius;
  for (int j = 0; j < 2; ++j) {
    const double s = dot(n, p[j] - r0);
    const double gap = s - radii;
    if (gap > alert) continue;
    ContactPoint c;
    // Surfaces: the incident one at p − n ri, the reference one at p − n (s − rr).
    const V2 mid = p[j] - (0.5 * (ri + s - rr)) * n;
    const V2 nn = ref_is_b ? n : -1.0 * n;
    c.point[0] = mid.x;
    c.point[1] = mid.y;
    c.normal[0] = nn.x;
    c.normal[1] = nn.y;
    c.gap = gap;
    c.feature = (ref_is_b ? 0 : 1 << 12) | static_cast<int>(r % 64) << 6 | (id[j] & 63);
    out.push_back(c);
  }
}

void disk_polygon(V2 c, double R, const Polygon& b, double alert, std::vector<ContactPoint>& out) {
  // Deepest edge (largest separation of the centre); outside: closest point on the boundary.
  double s_max = -std::numeric_limits<double>::infinity();
  std::size_t i_max = 0;
  for (std::size_t i = 0; i < b.v.size(); ++i) {
    const double s = dot(edge_normal(b, i), c - b.v[i]);
    if (s > s_max) {
      s_max = s;
      i_max = i;
    }
  }
  V2 n, q;
  double dist;
  if (s_max <= 0) {  // centre inside the core
    n = edge_normal(b, i_max);
    dist = s_max;
    q = c - s_max * n;
  } else {
    dist = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < b.v.size(); ++i) {
      const V2 p0 = b.v[i], e = b.v[(i + 1) % b.v.size()] - p0;
      const double f = std::clamp(dot(c - p0, e) / dot(e, e), 0.0, 1.0);
      const V2 p = p0 + f * e;
      const double d = norm(c - p);
      if (d < dist) {
        dist = d;
        q = p;
      }
    }
    n = dist > 0 ? (1 / dist) * (c - q) : edge_normal(b, i_max);
  }
  const double gap = dist - R - b.radius;
  if (gap > alert) return;
  ContactPoint cp;
  const V2 mid = q + (b.radius + gap / 2) * n;
  cp.point[0] = mid.x;
  cp.point[1] = mid.y;
  cp.normal[0] = n.x;
  cp.normal[1] = n.y;
  cp.gap = gap;
  out.push_back(cp);
}

}  // namespace moreau::geom
