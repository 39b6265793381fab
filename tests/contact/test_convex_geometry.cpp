// Convex geometry behind the polygon, box and convex shapes: mass properties against
// closed forms, hulls, and the contact manifolds their detectors produce.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <convex.hpp>
#include <stdexcept>

using namespace moreau;
using namespace moreau::geom;

namespace {
const double identity_q[4] = {1, 0, 0, 0};
const double zero_angle[1] = {0};
}  // namespace

TEST(ConvexGeometry, PolygonMassMatchesTheRectangle) {
  // 0.4 × 0.2 rectangle, given clockwise and shifted: area, centroid, polar moment.
  auto v = convex_polygon({{0, 0}, {0, 0.2}, {0.4, 0.2}, {0.4, 0}});
  const MassProperties m = polygon_mass(v);
  EXPECT_NEAR(m.volume, 0.08, 1e-15);
  EXPECT_NEAR(m.center[0], 0.2, 1e-15);
  EXPECT_NEAR(m.center[1], 0.1, 1e-15);
  EXPECT_NEAR(m.inertia[8], 0.08 * (0.16 + 0.04) / 12, 1e-15);
}

TEST(ConvexGeometry, DegeneratePolygonsAreRefusedWithTheReason) {
  auto message = [](std::vector<std::array<double, 2>> v) {
    try {
      convex_polygon(v);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(message({{0, 0}, {1, 0}}), "a polygon needs at least 3 vertices");
  EXPECT_EQ(message({{0, 0}, {1, 0}, {2, 0}}), "collinear vertices around vertex 1");
  EXPECT_NE(message({{0, 0}, {2, 0}, {1, 0.2}, {2, 1}, {0, 1}}).find("not convex"), std::string::npos);
  EXPECT_EQ(message({{0, 0}, {0, 0}, {1, 1}}), "repeated vertex 0");
}

TEST(ConvexGeometry, ConvexHullOfACubeAndItsMass) {
  std::vector<V3> cube;
  for (int i = 0; i < 8; ++i) cube.push_back({i & 1 ? 1.0 : 0.0, i & 2 ? 2.0 : 0.0, i & 4 ? 3.0 : 0.0});
  Polyhedron p;
  p.v = cube;
  p.faces = hull_faces(cube);
  EXPECT_EQ(p.faces.size(), 6u) << "coplanar triangles merge into the 6 faces";
  p.finish();
  for (std::size_t f = 0; f < p.faces.size(); ++f)
    EXPECT_GT(dot(p.normal[f], p.v[p.faces[f][0]] - p.centre), 0) << "face normals point outward";
  const MassProperties m = polyhedron_mass(p);
  EXPECT_NEAR(m.volume, 6, 1e-12);
  EXPECT_NEAR(m.center[0], 0.5, 1e-12);
  EXPECT_NEAR(m.center[2], 1.5, 1e-12);
  EXPECT_NEAR(m.inertia[0], 6 * (4 + 9) / 12.0, 1e-12);
  EXPECT_NEAR(m.inertia[4], 6 * (1 + 9) / 12.0, 1e-12);
  EXPECT_NEAR(m.inertia[8], 6 * (1 + 4) / 12.0, 1e-12);
  EXPECT_NEAR(m.inertia[1], 0, 1e-12);
  cube.push_back({0.5, 1, 1.5});
  EXPECT_THROW(hull_faces(cube), std::invalid_argument) << "an inner point is not a corner";
  EXPECT_THROW(hull_faces({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}}), std::invalid_argument) << "coplanar";
}

TEST(ConvexGeometry, BoxFacesPointOutward) {
  const double pos[3] = {0, 0, 0};
  const Polyhedron b = polyhedron_at("box", {1, 2, 3}, Pose{pos, identity_q});
  ASSERT_EQ(b.faces.size(), 6u);
  ASSERT_EQ(b.edges.size(), 12u);
  for (std::size_t f = 0; f < 6; ++f) EXPECT_NEAR(b.offset[f], std::fabs(b.normal[f].x) * 0.5 + std::fabs(b.normal[f].y) + std::fabs(b.normal[f].z) * 1.5, 1e-15);
}

TEST(ConvexGeometry, BoxOnBoxGivesFourPointsWithTheGap) {
  // A 1×1×1 box 0.01 above a 2×2×1 box, turned 30° about z: the upper face corners.
  const double pa[3] = {0, 0, 1.01}, pb[3] = {0, 0, 0};
  const double qa[4] = {std::cos(M_PI / 12), 0, 0, std::sin(M_PI / 12)};
  std::vector<ContactPoint> out;
  polyhedron_polyhedron(polyhedron_at("box", {1, 1, 1}, Pose{pa, qa}), polyhedron_at("box", {2, 2, 1}, Pose{pb, identity_q}),
                        0.02, out);
  ASSERT_EQ(out.size(), 4u);
  for (const auto& c : out) {
    EXPECT_NEAR(c.gap, 0.01, 1e-12);
    EXPECT_NEAR(c.normal[2], 1, 1e-12) << "from the second toward the first";
    EXPECT_NEAR(c.point[2], 0.505, 1e-12) << "midway in the gap";
    EXPECT_NEAR(std::hypot(c.point[0], c.point[1]), std::sqrt(0.5), 1e-12) << "at the upper box's corners";
  }
  out.clear();
  polyhedron_polyhedron(polyhedron_at("box", {1, 1, 1}, Pose{pa, qa}), polyhedron_at("box", {2, 2, 1}, Pose{pb, identity_q}),
                        0.005, out);
  EXPECT_TRUE(out.empty()) << "beyond the alert distance";
}

TEST(ConvexGeometry, CrossedEdgesGiveOnePoint) {
  // Two long bars crossing at right angles, edge on edge (each turned 45° about its axis).
  const double s = std::sqrt(0.5);
  const double pa[3] = {0, 0, std::sqrt(2.0) - 0.001}, pb[3] = {0, 0, 0};
  const double qa[4] = {std::cos(M_PI / 8), std::sin(M_PI / 8), 0, 0};  // bar along x, rolled about x
  const double qb[4] = {std::cos(M_PI / 8), 0, std::sin(M_PI / 8), 0};  // bar along y, rolled about y
  std::vector<ContactPoint> out;
  polyhedron_polyhedron(polyhedron_at("box", {4, 1, 1}, Pose{pa, qa}), polyhedron_at("box", {1, 4, 1}, Pose{pb, qb}), 0.01,
                        out);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_NEAR(out[0].gap, -0.001, 1e-9);
  EXPECT_NEAR(out[0].normal[2], 1, 1e-9);
  EXPECT_NEAR(out[0].point[2], s - 0.0005, 1e-9);
}

TEST(ConvexGeometry, SphereAgainstBoxFaceEdgeAndInside) {
  const double pb[3] = {0, 0, 0};
  const Polyhedron b = polyhedron_at("box", {2, 2, 2}, Pose{pb, identity_q});
  std::vector<ContactPoint> out;
  sphere_polyhedron({0.2, 0.3, 1.5}, 0.4, b, 0.2, out);  // above the top face
  ASSERT_EQ(out.size(), 1u);
  EXPECT_NEAR(out[0].gap, 0.1, 1e-15);
  EXPECT_NEAR(out[0].normal[2], 1, 1e-15);
  out.clear();
  sphere_polyhedron({1.3, 0, 1.4}, 0.4, b, 0.2, out);  // beside the top +x edge
  ASSERT_EQ(out.size(), 1u);
  EXPECT_NEAR(out[0].gap, 0.5 - 0.4, 1e-15);
  EXPECT_NEAR(out[0].normal[0], 0.6, 1e-15);
  EXPECT_NEAR(out[0].normal[2], 0.8, 1e-15);
  out.clear();
  sphere_polyhedron({0, 0, 0.9}, 0.4, b, 0.2, out);  // centre inside, closest face the top
  ASSERT_EQ(out.size(), 1u);
  EXPECT_NEAR(out[0].gap, -0.5, 1e-15);
  EXPECT_NEAR(out[0].normal[2], 1, 1e-15);
}

TEST(ConvexGeometry, BlockOnSlabGivesTwoPoints2D) {
  const double pa[2] = {0, 0.06}, pb[2] = {0, -0.5};
  Polygon a = polygon_at({4, -0.1, -0.05, 0.1, -0.05, 0.1, 0.05, -0.1, 0.05}, Pose{pa, zero_angle});
  Polygon b = polygon_at({4, -1, -0.5, 1, -0.5, 1, 0.5, -1, 0.5}, Pose{pb, zero_angle});
  std::vector<ContactPoint> out;
  polygon_polygon(a, b, 0.02, out);
  ASSERT_EQ(out.size(), 2u);
  for (const auto& c : out) {
    EXPECT_NEAR(c.gap, 0.01, 1e-15);
    EXPECT_NEAR(c.normal[1], 1, 1e-15);
    EXPECT_NEAR(c.point[1], 0.005, 1e-15);
    EXPECT_NEAR(std::fabs(c.point[0]), 0.1, 1e-15);
  }
  EXPECT_NE(out[0].feature, out[1].feature) << "distinct identities for the warm start";
  // The same block on a rounded segment of thickness 0.02 (its surface at y = 0.01).
  out.clear();
  const double ps[2] = {0, 0};
  polygon_polygon(a, segment_at({1.0, 0.02}, Pose{ps, zero_angle}), 0.1, out);
  ASSERT_EQ(out.size(), 2u);
  for (const auto& c : out) {
    EXPECT_NEAR(c.gap, 0.0, 1e-15);
    EXPECT_NEAR(c.point[1], 0.01, 1e-15);
  }
}

TEST(ConvexGeometry, DiskAgainstPolygonCorner) {
  const double pb[2] = {0, 0};
  Polygon b = polygon_at({4, -1, -1, 1, -1, 1, 1, -1, 1}, Pose{pb, zero_angle});
  std::vector<ContactPoint> out;
  disk_polygon({1.3, 1.4}, 0.4, b, 0.2, out);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_NEAR(out[0].gap, 0.1, 1e-15);
  EXPECT_NEAR(out[0].normal[0], 0.6, 1e-15);
}

namespace {
/// Signed distance-like measure of x from a polyhedron's surface: the largest face-plane
/// offset (0 on the surface, < 0 inside, > 0 outside; exact on the surface).
double face_plane_excess(const Polyhedron& p, V3 x) {
  double s = -1e300;
  for (std::size_t f = 0; f < p.faces.size(); ++f) s = std::max(s, dot(p.normal[f], x) - p.offset[f]);
  return s;
}
}  // namespace

TEST(ConvexGeometry, EveryContactPointSitsBetweenTheTwoSurfacesAtItsGap) {
  // Random boxes near each other (seeded): each contact's point ± gap/2 along the normal
  // must land on the surface of each body (to rounding when they overlap). A contact from the wrong pair of edges (for
  // boxes, 16 edge pairs share each axis) is placed away from where the bodies touch and
  // fails this.
  std::uint64_t seed = 12345;
  auto uniform = [&seed] {
    seed = seed * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(seed >> 11) / 9007199254740992.0;
  };
  auto random_rotation = [&](double* q) {
    double n = 0;
    for (int i = 0; i < 4; ++i) q[i] = uniform() * 2 - 1, n += q[i] * q[i];
    for (int i = 0; i < 4; ++i) q[i] /= std::sqrt(n);
  };
  int contacts = 0, edge_contacts = 0, vertex_face_contacts = 0, bad = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    double qa[4], qb[4];
    random_rotation(qa);
    random_rotation(qb);
    const std::vector<double> sa{0.5 + uniform(), 0.5 + uniform(), 0.5 + uniform()};
    const std::vector<double> sb{0.5 + uniform(), 0.5 + uniform(), 0.5 + uniform()};
    const double pb[3] = {0, 0, 0};
    const Polyhedron b = polyhedron_at("box", sb, Pose{pb, qb});
    // A along a random direction at about the distance where the two just touch.
    double dir[3], n2 = 0;
    for (double& d : dir) d = uniform() * 2 - 1, n2 += d * d;
    const double r = 0.3 + 1.2 * uniform();
    const double pa[3] = {r * dir[0] / std::sqrt(n2), r * dir[1] / std::sqrt(n2), r * dir[2] / std::sqrt(n2)};
    const Polyhedron a = polyhedron_at("box", sa, Pose{pa, qa});
    std::vector<ContactPoint> out;
    polyhedron_polyhedron(a, b, 0.05, out);
    for (const ContactPoint& c : out) {
      const V3 p{c.point[0], c.point[1], c.point[2]}, n{c.normal[0], c.normal[1], c.normal[2]};
      if (c.gap < -0.05) continue;  // deep overlap: the witnesses of SAT need not be unique
      ++contacts;
      edge_contacts += (c.feature >> 14) == 2;  // the edge-pair encoding
      const double on_a = face_plane_excess(a, p + (c.gap / 2) * n), on_b = face_plane_excess(b, p - (c.gap / 2) * n);
      // Overlapping or touching, the separating-axis witnesses are exact; apart, the
      // separation along the best axis is only a lower bound of the distance (the closest
      // features may be a vertex and an edge), so the point may be off by up to the gap.
      // Predictive vertex–face points are exact distances at any gap.
      const bool vertex_face = (c.feature >> 14) == 3;
      vertex_face_contacts += vertex_face;
      const double tol = c.gap <= 0 || vertex_face ? 1e-9 : c.gap;
      if (std::fabs(on_a) > tol || std::fabs(on_b) > tol) {
        if (++bad <= 5)
          ADD_FAILURE() << "trial " << trial << " feature " << c.feature << " gap " << c.gap << ": point + gap/2 n is "
                        << on_a << " off the first surface, point − gap/2 n " << on_b << " off the second";
      }
    }
  }
  EXPECT_EQ(bad, 0) << "of " << contacts << " contacts";
  EXPECT_GT(edge_contacts, 20) << "the sample exercises edge-edge contacts";
  EXPECT_GT(vertex_face_contacts, 20) << "and predictive vertex-face points";
}
