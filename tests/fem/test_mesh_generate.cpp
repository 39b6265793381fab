// Mesh generators: sizes, named sets, outward boundaries, determinism, errors.
#include <gtest/gtest.h>

#include <numbers>

#include "fem_test_util.hpp"
#include "mesh_check.hpp"

namespace moreau::fem {
namespace {

double total_measure(const Mesh& mesh) {
  double v = 0;
  for (int e = 0; e < mesh.element_count(); ++e) v += element_measure(mesh, e);
  return v;
}

/// Every boundary facet's normal points away from its element's centroid.
void expect_outward(const Mesh& mesh, const Facets& facets) {
  for (int f = 0; f < facets.size(); ++f) {
    const Eigen::Vector3d n = facet_normal(mesh, facets, f);
    Eigen::Vector3d d = Eigen::Vector3d::Zero();
    for (int v : facets.cells[f]) d.head(mesh.dim) += mesh.x.col(v) / static_cast<double>(facets.cells[f].size());
    const auto cell = mesh.elements[facets.element[f]];
    for (int v : cell) d.head(mesh.dim) -= mesh.x.col(v) / static_cast<double>(cell.size());
    ASSERT_GT(n.dot(d), 0) << "facet " << f;
  }
}

TEST(FemGenerate, RectangleCountsSetsAndArea) {
  for (ElementType type : {ElementType::Q4, ElementType::T3}) {
    const Mesh m = rectangle_mesh({1, -0.5}, {3, 1}, 0.25, type);
    check_mesh(m);
    EXPECT_EQ(m.dim, 2);
    EXPECT_EQ(m.node_count(), 13 * 5);
    EXPECT_EQ(m.element_count(), 12 * 4 * (type == ElementType::T3 ? 2 : 1));
    EXPECT_NEAR(total_measure(m), 3.0, 1e-13);
    EXPECT_EQ(m.boundary_set("boundary").size(), 2 * (12 + 4));
    EXPECT_EQ(m.boundary_set("xmin").size(), 4);
    EXPECT_EQ(m.boundary_set("ymax").size(), 12);
    for (int n : m.node_set("xmax")) EXPECT_DOUBLE_EQ(m.x(0, n), 4.0);
    for (int n : m.node_set("ymin")) EXPECT_DOUBLE_EQ(m.x(1, n), -0.5);
    EXPECT_EQ(m.node_set("xmin").size(), 5u);
    EXPECT_EQ(m.element_set("all").size(), static_cast<std::size_t>(m.element_count()));
    expect_outward(m, m.boundary_set("boundary"));
    expect_outward(m, m.boundary_set("ymax"));
  }
}

TEST(FemGenerate, BoxCountsSetsAndVolume) {
  for (ElementType type : {ElementType::H8, ElementType::T4}) {
    const Mesh m = box_mesh({0, 0, 0}, {2, 1, 0.5}, 0.25, type);
    check_mesh(m);
    const int nx = 8, ny = 4, nz = 2, per_face = type == ElementType::T4 ? 2 : 1;
    EXPECT_EQ(m.node_count(), 9 * 5 * 3);
    EXPECT_EQ(m.element_count(), nx * ny * nz * (type == ElementType::T4 ? 6 : 1));
    EXPECT_NEAR(total_measure(m), 1.0, 1e-13);
    // A conforming mesh: the boundary is only the box's sides (no internal face once).
    EXPECT_EQ(m.boundary_set("boundary").size(), 2 * per_face * (nx * ny + ny * nz + nx * nz));
    EXPECT_EQ(m.boundary_set("zmax").size(), per_face * nx * ny);
    for (int n : m.node_set("zmax")) EXPECT_DOUBLE_EQ(m.x(2, n), 0.5);
    expect_outward(m, m.boundary_set("boundary"));
  }
}

TEST(FemGenerate, DiskOnTheCircleAndAreaConverging) {
  const double R = 0.3;
  for (ElementType type : {ElementType::Q4, ElementType::T3}) {
    double previous_error = 0;
    int previous_nb = 0;
    for (double size : {0.1, 0.05, 0.025}) {
      const Mesh m = disk_mesh({1, 2}, R, size, type);
      check_mesh(m);
      const Facets& boundary = m.boundary_set("boundary");
      for (int n : m.node_set("boundary")) EXPECT_NEAR((m.x.col(n) - Eigen::Vector2d(1, 2)).norm(), R, 1e-14);
      expect_outward(m, boundary);
      // The area is that of the inscribed polygon, (nb/2) R² sin(2π/nb).
      const int nb = boundary.size();
      const double polygon = 0.5 * nb * R * R * std::sin(2 * std::numbers::pi / nb);
      EXPECT_NEAR(total_measure(m), polygon, 1e-13);
      const double error = std::numbers::pi * R * R - polygon;
      // O(h²): the area error goes as 1/nb² (the number of boundary edges, rounded up from R/size).
      if (previous_error > 0) EXPECT_NEAR(std::log(previous_error / error) / std::log(double(nb) / previous_nb), 2.0, 0.01);
      previous_error = error;
      previous_nb = nb;
      const int centre = m.node_set("centre").at(0);
      EXPECT_NEAR((m.x.col(centre) - Eigen::Vector2d(1, 2)).norm(), 0, 1e-15);
    }
  }
}

TEST(FemGenerate, Deterministic) {
  const Mesh a = disk_mesh({0, 0}, 1, 0.1, ElementType::T3), b = disk_mesh({0, 0}, 1, 0.1, ElementType::T3);
  EXPECT_EQ(a.x, b.x);
  EXPECT_EQ(a.elements.nodes, b.elements.nodes);
  const Mesh c = box_mesh({0, 0, 0}, {1, 1, 1}, 0.3, ElementType::T4), d = box_mesh({0, 0, 0}, {1, 1, 1}, 0.3, ElementType::T4);
  EXPECT_EQ(c.elements.nodes, d.elements.nodes);
}

TEST(FemGenerate, BadArgumentsAreRefused) {
  const auto message = [](auto&& f) {
    try {
      f();
    } catch (const MeshError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message([] { rectangle_mesh({0, 0}, {1, 1}, 0, ElementType::Q4); }),
            "rectangle mesh: size must be a finite value > 0, got 0");
  EXPECT_EQ(message([] { rectangle_mesh({0, 0}, {-1, 1}, 0.1, ElementType::Q4); }),
            "rectangle mesh: width must be a finite value > 0, got -1");
  EXPECT_EQ(message([] { box_mesh({0, 0, 0}, {1, 1, 1}, 0.1, ElementType::Q4); }),
            "box mesh: element type Q4 is not available; valid: T4, H8");
  EXPECT_EQ(message([] { disk_mesh({0, 0}, 1, 0.1, ElementType::H8); }),
            "disk mesh: element type H8 is not available; valid: T3, Q4");
  EXPECT_NE(message([] { box_mesh({0, 0, 0}, {1, 1, 1}, 1e-4, ElementType::H8); }).find("at most 1e+07"), std::string::npos);
}

}  // namespace
}  // namespace moreau::fem
