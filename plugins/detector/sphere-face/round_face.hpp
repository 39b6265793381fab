#pragma once
// A round shape (centre c, radius R; a mesh node or a polyhedron's corner: R = 0)
// against one boundary face of a mesh (its 3 or 4 nodes, counter-clockwise seen from
// outside): LMGC90's CSASp / PRASp test. Shared by `sphere-face`, `point-face`, and
// `box-face` / `convex-face` (which run it for each corner of the shape).
//  - Triangle: the closest point of its plane by barycentric coordinates (the weights).
//  - Quadrangle: the closest point of its bilinear surface x(ξ, η) = Σ N_i(ξ, η) x_i by
//    Gauss–Newton from the centre of [−1, 1]² (exact in one step on a parallelogram);
//    the weights are the bilinear N_i.
//  - The centre projects inside: the normal is the surface's there, the gap the signed
//    distance minus the radius. It projects outside and lies in front: the closest point
//    of the face's edges, the normal from it to the centre (a corner or an edge of the
//    mesh). Behind the face outside it, or deeper behind than the face is wide: no contact.
// The kernel keeps the nearest face per candidate and body (docs/contacts.md, "Meshes").
#include <algorithm>
#include <array>
#include <cmath>
#include <moreau/detector.hpp>

namespace moreau_mesh_contact {

using V = std::array<double, 3>;

inline V sub(const double* a, const double* b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline double dot(const V& a, const V& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline V cross(const V& a, const V& b) { return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; }

/// A point of the face: its position, interpolation weights, the unit normal there and
/// whether it lies inside the face.
struct Projection {
  V x;
  double w[4] = {0, 0, 0, 0};
  V n;
  bool inside = false;
};

// A point within rounding of a face's edge or corner is on it: two meshes whose boundary
// nodes coincide (a conforming interface) keep their contacts inside the faces, with
// exact zero weights off the corner, as the 2D edges do (round_edge.hpp). Without it a node
// at a corner projected just outside, at distance 0 from the corner: a NaN normal.
constexpr double on_face_tolerance = 1e-9;

/// Barycentric weights within the tolerance of 0 become 0 (the others renormalised), and
/// the point counts as inside.
inline void snap_to_triangle(Projection& f) {
  bool near = true;
  for (int i = 0; i < 3; ++i) near = near && f.w[i] >= -on_face_tolerance;
  if (!near) return;
  double sum = 0;
  for (int i = 0; i < 3; ++i) sum += (f.w[i] = f.w[i] <= on_face_tolerance ? 0.0 : f.w[i]);
  for (int i = 0; i < 3; ++i) f.w[i] /= sum;
  f.inside = true;
}

/// Bilinear coordinates within the tolerance outside [−1, 1] come back to its edge.
inline bool snap_to_square(double& xi, double& eta) {
  if (std::fabs(xi) > 1 + on_face_tolerance || std::fabs(eta) > 1 + on_face_tolerance) return false;
  xi = std::clamp(xi, -1.0, 1.0);
  eta = std::clamp(eta, -1.0, 1.0);
  return true;
}

inline Projection triangle(const double* p, const double* c) {
  const V e1 = sub(p + 3, p), e2 = sub(p + 6, p), r = sub(c, p);
  V n = cross(e1, e2);
  const double a = std::sqrt(dot(n, n));
  for (double& x : n) x /= a;
  // Barycentric coordinates of the projection: solve [e1 e2] (l1, l2) = r − (r·n) n.
  const double d11 = dot(e1, e1), d12 = dot(e1, e2), d22 = dot(e2, e2), r1 = dot(r, e1), r2 = dot(r, e2);
  const double det = d11 * d22 - d12 * d12;
  const double l1 = (d22 * r1 - d12 * r2) / det, l2 = (d11 * r2 - d12 * r1) / det;
  Projection out;
  out.w[0] = 1 - l1 - l2;
  out.w[1] = l1;
  out.w[2] = l2;
  out.n = n;
  for (int k = 0; k < 3; ++k) out.x[k] = p[k] + l1 * e1[k] + l2 * e2[k];
  out.inside = out.w[0] >= 0 && l1 >= 0 && l2 >= 0;
  snap_to_triangle(out);
  return out;
}

inline Projection quadrangle(const double* p, const double* c) {
  const double sx[4] = {-1, 1, 1, -1}, sy[4] = {-1, -1, 1, 1};
  double xi = 0, eta = 0;
  V x{}, dxi{}, deta{};
  auto evaluate = [&]() {
    x = dxi = deta = V{0, 0, 0};
    for (int i = 0; i < 4; ++i) {
      const double N = (1 + sx[i] * xi) * (1 + sy[i] * eta) / 4;
      const double Nx = sx[i] * (1 + sy[i] * eta) / 4, Ny = sy[i] * (1 + sx[i] * xi) / 4;
      for (int k = 0; k < 3; ++k) {
        x[k] += N * p[3 * i + k];
        dxi[k] += Nx * p[3 * i + k];
        deta[k] += Ny * p[3 * i + k];
      }
    }
  };
  for (int it = 0; it < 20; ++it) {
    evaluate();
    const V r = sub(c, x.data());
    const double a = dot(dxi, dxi), b = dot(dxi, deta), d = dot(deta, deta), g1 = dot(dxi, r), g2 = dot(deta, r);
    const double det = a * d - b * b;
    const double sxi = (d * g1 - b * g2) / det, seta = (a * g2 - b * g1) / det;
    xi = std::clamp(xi + sxi, -3.0, 3.0);
    eta = std::clamp(eta + seta, -3.0, 3.0);
    if (std::fabs(sxi) + std::fabs(seta) < 1e-13) break;
  }
  const bool inside = snap_to_square(xi, eta);
  evaluate();
  Projection out;
  out.x = x;
  for (int i = 0; i < 4; ++i) out.w[i] = (1 + sx[i] * xi) * (1 + sy[i] * eta) / 4;
  out.n = cross(dxi, deta);
  const double a = std::sqrt(dot(out.n, out.n));
  for (double& v : out.n) v /= a;
  out.inside = inside;
  return out;
}

/// Fills `cp` (point, normal, gap, the face's weights cp.weights[1]) and returns true
/// when the gap is below `alert`. `p`: the face's n nodes (3 values each).
inline bool round_face(const double* c, double R, const double* p, int n, double alert, moreau::ContactPoint& cp) {
  double size = 0;
  for (int i = 0; i < n; ++i) {
    const V e = sub(p + 3 * ((i + 1) % n), p + 3 * i);
    size = std::max(size, std::sqrt(dot(e, e)));
  }
  if (!(size > 0)) return false;
  const Projection f = n == 3 ? triangle(p, c) : quadrangle(p, c);
  const V r = sub(c, f.x.data());
  const double s = dot(r, f.n);
  if (s < -size) return false;
  V q = f.x, normal = f.n;
  double dist = s;
  double w[4] = {f.w[0], f.w[1], f.w[2], f.w[3]};
  if (!f.inside) {
    if (s <= 0) return false;
    // The closest point of the face's edges.
    dist = INFINITY;
    for (int i = 0; i < n; ++i) {
      const int j = (i + 1) % n;
      const V e = sub(p + 3 * j, p + 3 * i), ci = sub(c, p + 3 * i);
      const double t = std::clamp(dot(ci, e) / dot(e, e), 0.0, 1.0);
      const V d{ci[0] - t * e[0], ci[1] - t * e[1], ci[2] - t * e[2]};
      const double len = std::sqrt(dot(d, d));
      if (len < dist) {
        dist = len;
        for (int k = 0; k < 3; ++k) {
          q[k] = p[3 * i + k] + t * e[k];
          normal[k] = d[k] / len;
        }
        std::fill(w, w + 4, 0.0);
        w[i] = 1 - t;
        w[j] = t;
      }
    }
  }
  const double gap = dist - R;
  if (gap > alert) return false;
  for (int k = 0; k < 3; ++k) {
    cp.normal[k] = normal[k];
    cp.point[k] = q[k] + normal[k] * gap / 2;
  }
  cp.gap = gap;
  for (int i = 0; i < 4; ++i) cp.weights[1][i] = w[i];
  return true;
}

}  // namespace moreau_mesh_contact
