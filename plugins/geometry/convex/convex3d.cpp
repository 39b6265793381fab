// Convex polyhedra: placement, mass properties, and contacts by separating axes (face
// normals of both, cross products of edge pairs). A face axis gives a manifold: the
// incident face of the other body clipped against the reference face's side planes
// (Sutherland–Hodgman), reduced to 4 points; an edge pair gives one point. Vertices in
// front of a face, and edges facing edges, of the other body within the alert distance
// add predictive points.
#include <algorithm>
#include <limits>
#include <stdexcept>

#include "convex.hpp"

namespace moreau::geom {

namespace {
constexpr double inf = std::numeric_limits<double>::infinity();
}

void Polyhedron::finish() {
  normal.clear();
  offset.clear();
  edges.clear();
  edge_faces.clear();
  centre = {};
  for (const V3& x : v) centre = centre + x;
  centre = (1.0 / v.size()) * centre;
  for (const auto& f : faces) {
    V3 n{};  // Newell's normal: robust for any planar polygon
    for (std::size_t i = 0; i < f.size(); ++i) n = n + cross(v[f[i]], v[f[(i + 1) % f.size()]]);
    n = (1 / norm(n)) * n;
    normal.push_back(n);
    offset.push_back(dot(n, v[f[0]]));
  }
  // Each edge once, with the face listing it a→b (a < b) first and the one listing it b→a
  // second: one pass to number the edges, one to pair them (this runs at every detection).
  const std::size_t nv = v.size();
  std::vector<int> edge_of(nv * nv, -1);
  for (int pass = 0; pass < 2; ++pass)
    for (std::size_t fi = 0; fi < faces.size(); ++fi) {
      const auto& f = faces[fi];
      for (std::size_t i = 0; i < f.size(); ++i) {
        const int a = f[i], b = f[(i + 1) % f.size()];
        if (pass == 0 && a < b) {
          edge_of[a * nv + b] = static_cast<int>(edges.size());
          edges.push_back({a, b});
          edge_faces.push_back({static_cast<int>(fi), -1});
        } else if (pass == 1 && a > b) {
          edge_faces[edge_of[b * nv + a]][1] = static_cast<int>(fi);
        }
      }
    }
}

std::vector<double> box_geometry_as_convex(const std::vector<double>& s) {
  const double x = s[0] / 2, y = s[1] / 2, z = s[2] / 2;
  std::vector<double> g{8};
  for (int i = 0; i < 8; ++i) {
    g.push_back(i & 1 ? x : -x);
    g.push_back(i & 2 ? y : -y);
    g.push_back(i & 4 ? z : -z);
  }
  // Counter-clockwise seen from outside: -x, +x, -y, +y, -z, +z.
  const int faces[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  g.push_back(6);
  for (const auto& f : faces) {
    g.push_back(4);
    for (int i : f) g.push_back(i);
  }
  return g;
}

Polyhedron polyhedron_at(const std::string& shape, const std::vector<double>& g0, const Pose& pose) {
  const std::vector<double> boxg = shape == "box" ? box_geometry_as_convex(g0) : std::vector<double>{};
  const std::vector<double>& g = shape == "box" ? boxg : g0;
  Polyhedron p;
  const int nv = static_cast<int>(g[0]);
  const V3 x{pose.position[0], pose.position[1], pose.position[2]};
  for (int i = 0; i < nv; ++i) p.v.push_back(x + rotate(pose.rotation, V3{g[1 + 3 * i], g[2 + 3 * i], g[3 + 3 * i]}));
  std::size_t at = 1 + 3 * nv;
  const int nf = static_cast<int>(g[at++]);
  for (int f = 0; f < nf; ++f) {
    const int k = static_cast<int>(g[at++]);
    std::vector<int> face;
    for (int i = 0; i < k; ++i) face.push_back(static_cast<int>(g[at++]));
    p.faces.push_back(std::move(face));
  }
  p.finish();
  return p;
}

double polyhedron_half_width(const Polyhedron& p) {
  double w = std::numeric_limits<double>::infinity();
  for (std::size_t f = 0; f < p.faces.size(); ++f) {
    double across = 0;
    for (const V3& q : p.v) across = std::max(across, p.offset[f] - dot(p.normal[f], q));
    w = std::min(w, across);
  }
  return w / 2;
}

MassProperties polyhedron_mass(const Polyhedron& p) {
  // Sum over tetrahedra (origin, triangle of a face fan): volume, first moment and the
  // covariance ∫x xᵀ (det(A) · A C A ᵀ with C the canonical tetrahedron's covariance).
  double V = 0;
  V3 first{};
  double C[3][3] = {};
  for (const auto& f : p.faces)
    for (std::size_t i = 1; i + 1 < f.size(); ++i) {
      const V3 a = p.v[f[0]], b = p.v[f[i]], c = p.v[f[i + 1]];
      const double det = dot(a, cross(b, c));
      V += det / 6;
      first = first + (det / 24) * (a + b + c);
      const double A[3][3] = {{a.x, b.x, c.x}, {a.y, b.y, c.y}, {a.z, b.z, c.z}};
      for (int r = 0; r < 3; ++r)
        for (int s = 0; s < 3; ++s) {
          double sum = 0;  // (A C Aᵀ)_rs with C = (1/120)(1 + δ_ij)
          for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) sum += A[r][i] * (i == j ? 2.0 : 1.0) * A[s][j];
          C[r][s] += det * sum / 120;
        }
    }
  MassProperties m;
  m.volume = V;
  const V3 c = (1 / V) * first;
  m.center = {c.x, c.y, c.z};
  const double cc[3] = {c.x, c.y, c.z};
  for (int r = 0; r < 3; ++r)
    for (int s = 0; s < 3; ++s) C[r][s] -= V * cc[r] * cc[s];  // about the centroid
  const double tr = C[0][0] + C[1][1] + C[2][2];
  for (int r = 0; r < 3; ++r)
    for (int s = 0; s < 3; ++s) m.inertia[3 * r + s] = (r == s ? tr : 0) - C[r][s];
  return m;
}

namespace {

/// Largest separation of q from p's face planes (max over faces of min over q's vertices).
double face_separation(const Polyhedron& p, const Polyhedron& q, int& best) {
  double s_best = -inf;
  for (std::size_t f = 0; f < p.faces.size(); ++f) {
    double s = inf;
    for (const V3& w : q.v) s = std::min(s, dot(p.normal[f], w) - p.offset[f]);
    if (s > s_best) {
      s_best = s;
      best = static_cast<int>(f);
    }
  }
  return s_best;
}

/// Closest points of segments [p0, p1] and [q0, q1].
void closest_on_segments(V3 p0, V3 p1, V3 q0, V3 q1, V3& a, V3& b) {
  const V3 d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
  const double A = dot(d1, d1), E = dot(d2, d2), F = dot(d2, r), C = dot(d1, r), B = dot(d1, d2);
  const double den = A * E - B * B;
  double s = den > 1e-300 ? std::clamp((B * F - C * E) / den, 0.0, 1.0) : 0.0;
  double t = (B * s + F) / E;
  if (t < 0) {
    t = 0;
    s = std::clamp(-C / A, 0.0, 1.0);
  } else if (t > 1) {
    t = 1;
    s = std::clamp((B - C) / A, 0.0, 1.0);
  }
  a = p0 + s * d1;
  b = q0 + t * d2;
}

int edge_feature(int ea, int eb) { return 1 << 15 | ((ea * 64 + eb) & 0x3fff); }

bool known_point(const std::vector<ContactPoint>& out, std::size_t first, V3 x, double same) {
  for (std::size_t k = first; k < out.size(); ++k)
    if (norm(V3{out[k].point[0], out[k].point[1], out[k].point[2]} - x) <= same) return true;
  return false;
}

/// Whether direction m points strictly inside the normal cone of edge e (between the
/// normals of its two faces): the edge, not a face, is what p shows toward m.
bool in_edge_cone(const Polyhedron& p, int e, V3 m) {
  const V3 n1 = p.normal[p.edge_faces[e][0]], n2 = p.normal[p.edge_faces[e][1]];
  const V3 c = cross(n1, n2);
  const double eps = 1e-6 * norm(c);
  return eps > 0 && dot(cross(n1, m), c) > eps && dot(cross(m, n2), c) > eps;
}

/// Predictive edge–edge contacts the separating-axis step does not give: every pair of
/// edges whose closest points are inside both, apart by 0 < d ≤ alert along a direction
/// each edge faces (inside both normal cones). Like the vertex–face points, these catch
/// an edge coming down while the bodies touch elsewhere.
void edge_edge_contacts(const Polyhedron& a, const Polyhedron& b, double alert, double same, std::size_t first,
                        std::vector<ContactPoint>& out) {
  for (std::size_t i = 0; i < a.edges.size(); ++i) {
    const V3 a0 = a.v[a.edges[i][0]], da = a.v[a.edges[i][1]] - a0;
    for (std::size_t j = 0; j < b.edges.size(); ++j) {
      const V3 b0 = b.v[b.edges[j][0]], db = b.v[b.edges[j][1]] - b0;
      V3 pa, pb;
      closest_on_segments(a0, a0 + da, b0, b0 + db, pa, pb);
      const double d = norm(pa - pb);
      if (d <= same || d > alert) continue;
      const V3 n = (1 / d) * (pa - pb);
      // Inside both edges, the joining segment is square to both (else an end is closest).
      if (std::fabs(dot(n, da)) > 1e-9 * norm(da) || std::fabs(dot(n, db)) > 1e-9 * norm(db)) continue;
      if (!in_edge_cone(a, static_cast<int>(i), -n) || !in_edge_cone(b, static_cast<int>(j), n)) continue;
      const V3 mid = 0.5 * (pa + pb);
      if (known_point(out, first, mid, same)) continue;
      ContactPoint c;
      c.point[0] = mid.x, c.point[1] = mid.y, c.point[2] = mid.z;
      c.normal[0] = n.x, c.normal[1] = n.y, c.normal[2] = n.z;
      c.gap = d;
      c.feature = edge_feature(static_cast<int>(i), static_cast<int>(j));
      out.push_back(c);
    }
  }
}

/// Predictive vertex–face contacts the separating-axis step does not give: every vertex
/// of `owner` in front of a face of `other` (0 ≤ distance ≤ alert) whose projection falls
/// inside that face, so its distance to `other` is exact. The axis step yields only the
/// closest feature pair; a body pivoting on an edge would otherwise bring its far corner
/// down with no contact to stop it within the step. Skips the vertices of `skip_face` of
/// `owner` (-1: none) and points the manifold already has.
void vertex_face_contacts(const Polyhedron& owner, const Polyhedron& other, bool owner_is_a, int skip_face, double alert,
                          double same, std::size_t first, std::vector<ContactPoint>& out) {
  for (std::size_t i = 0; i < owner.v.size(); ++i) {
    const V3 x = owner.v[i];
    if (skip_face >= 0 && std::find(owner.faces[skip_face].begin(), owner.faces[skip_face].end(), static_cast<int>(i)) !=
                              owner.faces[skip_face].end())
      continue;
    double s = -inf;
    int f = 0;
    for (std::size_t g = 0; g < other.faces.size(); ++g) {
      const double sg = dot(other.normal[g], x) - other.offset[g];
      if (sg > s) s = sg, f = static_cast<int>(g);
    }
    if (s < 0 || s > alert) continue;
    const V3 n = other.normal[f], foot = x - s * n;
    const auto& fv = other.faces[f];
    bool inside = true;
    for (std::size_t k = 0; k < fv.size() && inside; ++k)
      inside = dot(cross(other.v[fv[(k + 1) % fv.size()]] - other.v[fv[k]], n), foot - other.v[fv[k]]) <= 0;
    if (!inside) continue;
    const V3 mid = x - (s / 2) * n;
    if (known_point(out, first, mid, same)) continue;
    ContactPoint c;
    const V3 nn = owner_is_a ? n : -n;
    c.point[0] = mid.x, c.point[1] = mid.y, c.point[2] = mid.z;
    c.normal[0] = nn.x, c.normal[1] = nn.y, c.normal[2] = nn.z;
    c.gap = s;
    c.feature = 3 << 14 | (owner_is_a ? 0 : 1 << 13) | (f & 0x1f) << 8 | (static_cast<int>(i) & 0xff);
    out.push_back(c);
  }
}

}  // namespace

void polyhedron_polyhedron(const Polyhedron& a, const Polyhedron& b, double alert, std::vector<ContactPoint>& out) {
  int fa = 0, fb = 0;
  const double sa = face_separation(a, b, fa);
  if (sa > alert) return;
  const double sb = face_separation(b, a, fb);
  if (sb > alert) return;
  double size = 0;
  for (const V3& x : a.v) size = std::max(size, norm(x - a.centre));
  for (const V3& x : b.v) size = std::max(size, norm(x - b.centre));
  // Edge pairs: axis e_a × e_b, oriented from b toward a. A pair counts only if both
  // edges are the supporting features along its axis (a's edge at a's minimum, b's at
  // b's maximum), i.e. the pair spans a face of the Minkowski difference: parallel edges
  // give the same axis (16 pairs per axis for two boxes), and only the supporting pair
  // touches; the closest points of another pair are elsewhere.
  const double support_tol = 1e-9 * size;
  double se = -inf;
  int ea = -1, eb = -1;
  V3 axis_best{};
  const V3 towards_a = a.centre - b.centre;
  for (std::size_t i = 0; i < a.edges.size(); ++i) {
    const V3 da = a.v[a.edges[i][1]] - a.v[a.edges[i][0]];
    for (std::size_t j = 0; j < b.edges.size(); ++j) {
      const V3 db = b.v[b.edges[j][1]] - b.v[b.edges[j][0]];
      V3 ax = cross(da, db);
      const double l = norm(ax);
      if (l <= 1e-6 * norm(da) * norm(db)) continue;  // parallel edges: covered by face axes
      ax = (1 / l) * ax;
      if (dot(ax, towards_a) < 0) ax = -ax;
      double amin = inf, bmax = -inf;
      for (const V3& x : a.v) amin = std::min(amin, dot(ax, x));
      for (const V3& x : b.v) bmax = std::max(bmax, dot(ax, x));
      const double s = amin - bmax;
      const bool supporting = dot(ax, a.v[a.edges[i][0]]) <= amin + support_tol && dot(ax, b.v[b.edges[j][0]]) >= bmax - support_tol;
      if (!supporting) continue;
      if (s > se) {
        se = s;
        ea = static_cast<int>(i);
        eb = static_cast<int>(j);
        axis_best = ax;
      }
    }
  }
  if (se > alert) return;
  // Faces are preferred unless an edge pair separates clearly better: face contacts give
  // manifolds, and the bias keeps the choice stable from step to step.
  const double face_best = std::max(sa, sb);
  const std::size_t first = out.size();
  const double same = 1e-6 * size;  // two points closer than this are one contact
  if (ea >= 0 && se > face_best + 1e-3 * size) {
    V3 pa, pb;
    closest_on_segments(a.v[a.edges[ea][0]], a.v[a.edges[ea][1]], b.v[b.edges[eb][0]], b.v[b.edges[eb][1]], pa, pb);
    ContactPoint c;
    const V3 mid = 0.5 * (pa + pb);
    c.point[0] = mid.x, c.point[1] = mid.y, c.point[2] = mid.z;
    c.normal[0] = axis_best.x, c.normal[1] = axis_best.y, c.normal[2] = axis_best.z;
    c.gap = se;
    c.feature = edge_feature(ea, eb);
    out.push_back(c);
    edge_edge_contacts(a, b, alert, same, first, out);
    vertex_face_contacts(a, b, true, -1, alert, same, first, out);
    vertex_face_contacts(b, a, false, -1, alert, same, first, out);
    return;
  }
  const bool ref_is_b = sb >= sa - 1e-9 * (1 + std::fabs(sa));
  const Polyhedron& ref = ref_is_b ? b : a;
  const Polyhedron& inc = ref_is_b ? a : b;
  const int rf = ref_is_b ? fb : fa;
  const V3 n = ref.normal[rf];
  int inc_face = 0;
  double lowest = inf;
  for (std::size_t f = 0; f < inc.faces.size(); ++f)
    if (dot(inc.normal[f], n) < lowest) {
      lowest = dot(inc.normal[f], n);
      inc_face = static_cast<int>(f);
    }
  struct Pt {
    V3 x;
    int id;
  };
  std::vector<Pt> poly, next;
  for (std::size_t i = 0; i < inc.faces[inc_face].size(); ++i) poly.push_back({inc.v[inc.faces[inc_face][i]], static_cast<int>(i)});
  const auto& rface = ref.faces[rf];
  for (std::size_t e = 0; e < rface.size() && !poly.empty(); ++e) {
    const V3 r0 = ref.v[rface[e]], r1 = ref.v[rface[(e + 1) % rface.size()]];
    const V3 side = cross(r1 - r0, n);  // outward across this edge of the reference face
    next.clear();
    for (std::size_t i = 0; i < poly.size(); ++i) {
      const Pt& p = poly[i];
      const Pt& q = poly[(i + 1) % poly.size()];
      const double dp = dot(side, p.x - r0), dq = dot(side, q.x - r0);
      if (dp <= 0) next.push_back(p);
      if ((dp < 0 && dq > 0) || (dp > 0 && dq < 0)) {
        const double f = dp / (dp - dq);
        next.push_back({p.x + f * (q.x - p.x), 32 + static_cast<int>(e % 8) * 4 + (p.id & 3)});
      }
    }
    poly.swap(next);
  }
  for (const Pt& p : poly) {
    const double s = dot(n, p.x) - ref.offset[rf];
    if (s > alert) continue;
    ContactPoint c;
    const V3 mid = p.x - (s / 2) * n;
    const V3 nn = ref_is_b ? n : -n;
    c.point[0] = mid.x, c.point[1] = mid.y, c.point[2] = mid.z;
    c.normal[0] = nn.x, c.normal[1] = nn.y, c.normal[2] = nn.z;
    c.gap = s;
    c.feature = (ref_is_b ? 0 : 1 << 14) | (rf & 0x3f) << 8 | (p.id & 0xff);
    out.push_back(c);
  }
  reduce_manifold(out, first);
  // The two clipped faces' vertices are the manifold's (its reduction dropped some on
  // purpose); only the other vertices can add points.
  edge_edge_contacts(a, b, alert, same, first, out);
  vertex_face_contacts(inc, ref, ref_is_b, inc_face, alert, same, first, out);
  vertex_face_contacts(ref, inc, !ref_is_b, rf, alert, same, first, out);
}

void polyhedron_plane(const Polyhedron& a, V3 n, V3 p, double alert, std::vector<ContactPoint>& out) {
  const std::size_t first = out.size();
  for (std::size_t i = 0; i < a.v.size(); ++i) {
    const double s = dot(n, a.v[i] - p);
    if (s > alert) continue;
    ContactPoint c;
    const V3 mid = a.v[i] - (s / 2) * n;
    c.point[0] = mid.x, c.point[1] = mid.y, c.point[2] = mid.z;
    c.normal[0] = n.x, c.normal[1] = n.y, c.normal[2] = n.z;
    c.gap = s;
    c.feature = static_cast<int>(i);
    out.push_back(c);
  }
  reduce_manifold(out, first);
}

void sphere_polyhedron(V3 c, double R, const Polyhedron& b, double alert, std::vector<ContactPoint>& out) {
  double s_max = -inf;
  int f_max = 0;
  for (std::size_t f = 0; f < b.faces.size(); ++f) {
    const double s = dot(b.normal[f], c) - b.offset[f];
    if (s > s_max) {
      s_max = s;
      f_max = static_cast<int>(f);
    }
  }
  V3 n, q;
  double dist;
  if (s_max <= 0) {  // centre inside: the closest face
    n = b.normal[f_max];
    dist = s_max;
    q = c - s_max * n;
  } else {  // closest point on the surface: on a face, else on an edge
    dist = inf;
    for (std::size_t f = 0; f < b.faces.size(); ++f) {
      const double s = dot(b.normal[f], c) - b.offset[f];
      if (s < 0) continue;  // the centre is behind this face: its closest point is elsewhere
      const V3 proj = c - s * b.normal[f];
      bool inside = true;
      const auto& fv = b.faces[f];
      for (std::size_t i = 0; i < fv.size() && inside; ++i)
        inside = dot(cross(b.v[fv[(i + 1) % fv.size()]] - b.v[fv[i]], b.normal[f]), proj - b.v[fv[i]]) <= 0;
      if (inside && s < dist) {
        dist = s;
        q = proj;
      }
    }
    for (const auto& e : b.edges) {
      const V3 p0 = b.v[e[0]], d = b.v[e[1]] - p0;
      const double t = std::clamp(dot(c - p0, d) / dot(d, d), 0.0, 1.0);
      const V3 p = p0 + t * d;
      if (norm(c - p) < dist) {
        dist = norm(c - p);
        q = p;
      }
    }
    n = dist > 0 ? (1 / dist) * (c - q) : b.normal[f_max];
  }
  const double gap = dist - R;
  if (gap > alert) return;
  ContactPoint cp;
  const V3 mid = q + (gap / 2) * n;
  cp.point[0] = mid.x, cp.point[1] = mid.y, cp.point[2] = mid.z;
  cp.normal[0] = n.x, cp.normal[1] = n.y, cp.normal[2] = n.z;
  cp.gap = gap;
  out.push_back(cp);
}

}  // namespace moreau::geom
