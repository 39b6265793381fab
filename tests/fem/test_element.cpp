// Reference elements: shape functions, derivatives, integration rules, face tables.
#include <gtest/gtest.h>

#include "element.hpp"
#include "fem_test_util.hpp"

namespace moreau::fem {
namespace {

const ElementType all_types[] = {ElementType::L2, ElementType::T3, ElementType::Q4, ElementType::T4, ElementType::H8};

TEST(FemElement, ShapeFunctionsInterpolateAtNodesAndSumToOne) {
  // Reference node coordinates in each type's node order.
  const std::vector<std::vector<std::array<double, 3>>> nodes = {
      {{-1, 0, 0}, {1, 0, 0}},
      {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}},
      {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}},
      {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}},
      {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1}, {-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}}};
  for (int t = 0; t < 5; ++t) {
    const ElementInfo& info = element_info(all_types[t]);
    ASSERT_EQ(static_cast<int>(nodes[t].size()), info.nodes);
    double N[8];
    for (int a = 0; a < info.nodes; ++a) {
      shape_functions(info.type, nodes[t][a].data(), N);
      for (int b = 0; b < info.nodes; ++b) EXPECT_NEAR(N[b], a == b ? 1.0 : 0.0, 1e-15) << info.name;
    }
    for (const QuadraturePoint& q : info.rule) {
      shape_functions(info.type, q.xi.data(), N);
      double sum = 0;
      for (int a = 0; a < info.nodes; ++a) sum += N[a];
      EXPECT_NEAR(sum, 1.0, 1e-15) << info.name;
    }
  }
}

TEST(FemElement, DerivativesMatchFiniteDifferences) {
  const double xi[3] = {0.21, 0.13, 0.34}, eps = 1e-6;
  for (ElementType type : all_types) {
    const ElementInfo& info = element_info(type);
    double dN[24], Np[8], Nm[8];
    shape_derivatives(type, xi, dN);
    for (int k = 0; k < info.dim; ++k) {
      double p[3] = {xi[0], xi[1], xi[2]}, m[3] = {xi[0], xi[1], xi[2]};
      p[k] += eps;
      m[k] -= eps;
      shape_functions(type, p, Np);
      shape_functions(type, m, Nm);
      for (int a = 0; a < info.nodes; ++a)
        EXPECT_NEAR(dN[a * info.dim + k], (Np[a] - Nm[a]) / (2 * eps), 1e-9) << info.name << " node " << a;
    }
  }
}

TEST(FemElement, RulesIntegrateQuadraticsExactly) {
  // ∫ 1 and ∫ ξ0² over each reference element (the consistent mass needs degree 2 on
  // simplices and degree 2 per direction, times a bilinear Jacobian, on Q4/H8).
  struct Expect {
    ElementType type;
    double measure, xi0_squared;
  };
  const Expect expect[] = {{ElementType::L2, 2, 2.0 / 3},     {ElementType::T3, 0.5, 1.0 / 12},
                           {ElementType::Q4, 4, 4.0 / 3},     {ElementType::T4, 1.0 / 6, 1.0 / 60},
                           {ElementType::H8, 8, 8.0 / 3}};
  for (const Expect& e : expect) {
    double measure = 0, second = 0;
    for (const QuadraturePoint& q : element_info(e.type).rule) {
      measure += q.weight;
      second += q.weight * q.xi[0] * q.xi[0];
    }
    EXPECT_NEAR(measure, e.measure, 1e-15) << element_info(e.type).name;
    EXPECT_NEAR(second, e.xi0_squared, 1e-15) << element_info(e.type).name;
  }
}

TEST(FemElement, FacesOfTheTableAreOutward) {
  for (ElementType type : test::volume_types()) {
    Mesh mesh = test::one_element(type);
    const Facets faces = boundary_facets(mesh);
    ASSERT_EQ(faces.size(), static_cast<int>(element_info(type).faces.size()));
    const Eigen::VectorXd centre = mesh.x.rowwise().mean();
    double total = 0;
    Eigen::Vector3d closure = Eigen::Vector3d::Zero();
    for (int f = 0; f < faces.size(); ++f) {
      double area = 0;
      const Eigen::Vector3d n = facet_normal(mesh, faces, f, &area);
      Eigen::Vector3d c = Eigen::Vector3d::Zero();
      for (int v : faces.cells[f]) c.head(mesh.dim) += mesh.x.col(v);
      c /= static_cast<double>(faces.cells[f].size());
      Eigen::Vector3d d = c;
      d.head(mesh.dim) -= centre;
      EXPECT_GT(n.dot(d), 0) << element_info(type).name << " face " << f;
      closure += area * n;
      total += area;
    }
    // A closed surface: Σ n dS = 0 (exact for flat faces: every face here is flat or,
    // for the H8's warped quads, the diagonal cross product is the exact vector area).
    EXPECT_LT(closure.norm(), 1e-12 * total) << element_info(type).name;
  }
}

TEST(FemElement, MirrorReversesTheOrientation) {
  for (ElementType type : test::volume_types()) {
    Mesh m = test::one_element(type);
    const double before = element_measure(m, 0);
    reverse_orientation(type, m.elements.at(0));
    EXPECT_NEAR(element_measure(m, 0), -before, 1e-14) << element_info(type).name;
    reverse_orientation(type, m.elements.at(0));
    EXPECT_EQ(m.elements[0][1], 1);  // an involution
  }
}

TEST(FemElement, GmshNumbers) {
  ElementType t;
  ASSERT_TRUE(element_type_from_gmsh(5, t));
  EXPECT_EQ(t, ElementType::H8);
  EXPECT_FALSE(element_type_from_gmsh(9, t));  // 6-node triangle: not yet
}

}  // namespace
}  // namespace moreau::fem
