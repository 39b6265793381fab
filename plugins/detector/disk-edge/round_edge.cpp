// `disk-edge` (LMGC90's DKALp) and `point-edge` (CLALp: a mesh node, radius 0): a round
// shape against one boundary edge of a mesh (shape `edge`, placed by its two nodes in
// Pose::nodes; its direction turned by −90° is the outward normal).
//  - The centre projects inside the edge: the normal is the edge's, the gap the signed
//    distance to its line minus the radius; weights (1 − t, t) on its nodes.
//  - It projects past an end (by more than 1e-9 of the edge) and lies in front: the closest point is that node, the normal
//    points from it to the centre (a corner of the mesh).
//  - It lies behind the line past an end, or deeper behind it than the edge is long: no
//    contact (the neighbouring edge, or the other side of a thin body, owns it).
// A candidate is thus found against every edge close enough; the kernel keeps the nearest
// per body (docs/contacts.md, "Meshes").
#include <algorithm>
#include <cmath>
#include <moreau/detector.hpp>

namespace {
using namespace moreau;

class RoundEdge : public Detector {
 public:
  static Schema schema() {
    Schema s;
    s.dimensions({2});
    return s;
  }
  static constexpr const char* doc = "a round shape (disk, or a mesh node) against a boundary edge of a mesh";
  RoundEdge(const Params&, const BuildContext&) {}
  void detect(int, const Shape& round, const Pose& a, const Shape&, const Pose& b, double alert,
              std::vector<ContactPoint>& out) const override {
    const double R = round.geometry()[0];
    const double* p0 = b.nodes;
    const double* p1 = b.nodes + 3;
    const double ex = p1[0] - p0[0], ey = p1[1] - p0[1], L2 = ex * ex + ey * ey;
    if (!(L2 > 0)) return;
    const double L = std::sqrt(L2), nx = ey / L, ny = -ex / L;
    const double cx = a.position[0] - p0[0], cy = a.position[1] - p0[1];
    const double t = (cx * ex + cy * ey) / L2, s = cx * nx + cy * ny;
    if (s < -L) return;
    // A node within rounding of an edge's end is on the edge: two meshes whose boundary
    // nodes coincide (a conforming interface) keep their contacts at the corners.
    constexpr double end_tolerance = 1e-9;
    double qt = std::clamp(t, 0.0, 1.0), gx = nx, gy = ny, dist = s;
    if (t < -end_tolerance || t > 1 + end_tolerance) {
      if (s <= 0) return;
      qt = std::clamp(t, 0.0, 1.0);
      const double dx = cx - qt * ex, dy = cy - qt * ey;
      dist = std::hypot(dx, dy);
      gx = dx / dist;
      gy = dy / dist;
    }
    const double gap = dist - R;
    if (gap > alert) return;
    ContactPoint c;
    c.normal[0] = gx;
    c.normal[1] = gy;
    c.point[0] = p0[0] + qt * ex + gx * gap / 2;
    c.point[1] = p0[1] + qt * ey + gy * gap / 2;
    c.gap = gap;
    c.weights[1][0] = 1 - qt;
    c.weights[1][1] = qt;
    out.push_back(c);
  }
};
MOREAU_REGISTER(RoundEdge, DETECTOR_NAME)
}  // namespace
MOREAU_PLUGIN_LIBRARY("moreau_detector_" DETECTOR_NAME)
