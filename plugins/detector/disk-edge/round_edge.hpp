#pragma once
// A round shape (centre c, radius R; a mesh node or a polygon's corner: R = 0) against one
// boundary edge of a mesh (its two nodes p0, p1; the direction p0 → p1 turned by −90° is
// the outward normal): LMGC90's DKALp / CLALp / PLALp test. Shared by `disk-edge`,
// `point-edge` and `polygon-edge` (which runs it for each corner of the polygon).
//  - The centre projects inside the edge: the normal is the edge's, the gap the signed
//    distance to its line minus the radius; weights (1 − t, t) on its nodes.
//  - It projects past an end (by more than 1e-9 of the edge) and lies in front: the
//    closest point is that node, the normal points from it to the centre (a corner of
//    the mesh).
//  - It lies behind the line past an end, or deeper behind it than the edge is long: no
//    contact (the neighbouring edge, or the other side of a thin body, owns it).
// A candidate is thus found against every edge close enough; the kernel keeps the nearest
// per body (docs/contacts.md, "Meshes").
#include <algorithm>
#include <cmath>
#include <moreau/detector.hpp>

namespace moreau_mesh_contact {

/// Fills `c` (point, normal, gap, the edge's weights c.weights[1]) and returns true when
/// the gap is below `alert`.
inline bool round_edge(const double* centre, double R, const double* p0, const double* p1, double alert,
                       moreau::ContactPoint& c) {
  const double ex = p1[0] - p0[0], ey = p1[1] - p0[1], L2 = ex * ex + ey * ey;
  if (!(L2 > 0)) return false;
  const double L = std::sqrt(L2), nx = ey / L, ny = -ex / L;
  const double cx = centre[0] - p0[0], cy = centre[1] - p0[1];
  const double t = (cx * ex + cy * ey) / L2, s = cx * nx + cy * ny;
  if (s < -L) return false;
  // A node within rounding of an edge's end is on the edge: two meshes whose boundary
  // nodes coincide (a conforming interface) keep their contacts at the corners.
  constexpr double end_tolerance = 1e-9;
  double qt = std::clamp(t, 0.0, 1.0), gx = nx, gy = ny, dist = s;
  if (t < -end_tolerance || t > 1 + end_tolerance) {
    if (s <= 0) return false;
    const double dx = cx - qt * ex, dy = cy - qt * ey;
    dist = std::hypot(dx, dy);
    gx = dx / dist;
    gy = dy / dist;
  }
  const double gap = dist - R;
  if (gap > alert) return false;
  c.normal[0] = gx;
  c.normal[1] = gy;
  c.point[0] = p0[0] + qt * ex + gx * gap / 2;
  c.point[1] = p0[1] + qt * ey + gy * gap / 2;
  c.gap = gap;
  c.weights[1][0] = 1 - qt;
  c.weights[1][1] = qt;
  return true;
}

}  // namespace moreau_mesh_contact
