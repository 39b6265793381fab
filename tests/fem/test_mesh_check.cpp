// Mesh checks: inverted and degenerate elements, non-finite coordinates.
#include <gtest/gtest.h>

#include "fem_test_util.hpp"
#include "mesh_check.hpp"

namespace moreau::fem {
namespace {

std::string check_error(const Mesh& mesh, std::int64_t* element = nullptr) {
  try {
    check_mesh(mesh);
  } catch (const MeshError& e) {
    if (element) *element = e.element();
    return e.what();
  }
  return "no error";
}

TEST(FemCheck, GeneratedMeshesPassEveryType) {
  for (ElementType type : test::volume_types()) EXPECT_EQ(check_error(test::one_element(type)), "no error");
}

TEST(FemCheck, InvertedQuadrangle) {
  // Node 5 (the centre of a 2 × 2 Q4 mesh) pushed past the far corner (2, 2): element 4
  // (nodes 5 6 9 8, the top right one) folds over; the others stay valid.
  Mesh m = rectangle_mesh({0, 0}, {2, 2}, 1, ElementType::Q4);
  m.x.col(4) << 2.5, 2.5;
  std::int64_t element = 0;
  const std::string message = check_error(m, &element);
  EXPECT_NE(message.find("rectangle: "), std::string::npos) << message;
  EXPECT_NE(message.find("rectangle: 1 inverted or degenerate element\n  element 4 of the rectangle mesh (Q4) is inverted: Jacobian determinant"), std::string::npos)
      << message;
  EXPECT_EQ(element, 4);
}

TEST(FemCheck, DegenerateAndManyFaults) {
  // All nodes of a row collapsed onto the row below: every element of that row is flat.
  Mesh m = rectangle_mesh({0, 0}, {12, 1}, 1, ElementType::T3);
  for (int i = 0; i <= 12; ++i) m.x(1, 13 + i) = 0;
  const std::string message = check_error(m);
  EXPECT_NE(message.find("rectangle: 24 inverted or degenerate elements"), std::string::npos) << message;
  EXPECT_NE(message.find("element 1 of the rectangle mesh (T3) is degenerate: Jacobian determinant 0"), std::string::npos)
      << message;
  EXPECT_NE(message.find("… and 14 more"), std::string::npos) << message;
}

TEST(FemCheck, TinyButValidElementsPass) {
  // The test is relative to each element's size: a 1e-6 m mesh is fine.
  EXPECT_EQ(check_error(box_mesh({0, 0, 0}, {1e-6, 1e-6, 1e-6}, 0.5e-6, ElementType::T4)), "no error");
}

TEST(FemCheck, NonFiniteCoordinate) {
  Mesh m = rectangle_mesh({0, 0}, {1, 1}, 1, ElementType::Q4);
  m.x(0, 2) = std::nan("");
  EXPECT_EQ(check_error(m), "node 3 of rectangle has a non-finite coordinate");
}

TEST(FemCheck, StructuralFaults) {
  Mesh m = rectangle_mesh({0, 0}, {1, 1}, 1, ElementType::Q4);
  m.x.conservativeResize(2, 5);
  m.x.col(4) << 3, 3;
  EXPECT_EQ(check_error(m), "node 5 of rectangle belongs to no element (it would be free to move with no stiffness)");
  Mesh t = test::one_element(ElementType::T4);
  t.dim = 2;
  t.x.conservativeResize(2, 4);
  EXPECT_EQ(check_error(t), "element 1 of the one-element mesh is a T4 with 4 nodes in a 2D mesh");
  Mesh q = test::one_element(ElementType::Q4);
  q.elements.nodes[3] = 7;
  EXPECT_EQ(check_error(q), "element 1 of the one-element mesh refers to node index 7, outside [0, 4)");
}

}  // namespace
}  // namespace moreau::fem
