// The table of reference elements (see element.hpp for the conventions).
#include "element.hpp"

#include <cmath>
#include <stdexcept>

namespace moreau::fem {
namespace {

constexpr double g2 = 0.57735026918962576451;  // 1/√3: 2-point Gauss abscissa
// 4-point rule of degree 2 on the tetrahedron: a = (5 − √5)/20, b = (5 + 3√5)/20.
constexpr double ta = 0.13819660112501051518, tb = 0.58541019662496845446;

constexpr QuadraturePoint rule_l2[] = {{{-g2, 0, 0}, 1.0}, {{g2, 0, 0}, 1.0}};
constexpr QuadraturePoint rule_t3[] = {
    {{1.0 / 6, 1.0 / 6, 0}, 1.0 / 6}, {{2.0 / 3, 1.0 / 6, 0}, 1.0 / 6}, {{1.0 / 6, 2.0 / 3, 0}, 1.0 / 6}};
constexpr QuadraturePoint rule_q4[] = {
    {{-g2, -g2, 0}, 1.0}, {{g2, -g2, 0}, 1.0}, {{g2, g2, 0}, 1.0}, {{-g2, g2, 0}, 1.0}};
constexpr QuadraturePoint rule_t4[] = {{{ta, ta, ta}, 1.0 / 24}, {{tb, ta, ta}, 1.0 / 24},
                                       {{ta, tb, ta}, 1.0 / 24}, {{ta, ta, tb}, 1.0 / 24}};
constexpr QuadraturePoint rule_h8[] = {
    {{-g2, -g2, -g2}, 1.0}, {{g2, -g2, -g2}, 1.0}, {{g2, g2, -g2}, 1.0}, {{-g2, g2, -g2}, 1.0},
    {{-g2, -g2, g2}, 1.0},  {{g2, -g2, g2}, 1.0},  {{g2, g2, g2}, 1.0},  {{-g2, g2, g2}, 1.0}};

using E = ElementType;
constexpr FaceInfo faces_t3[] = {{E::L2, {0, 1}}, {E::L2, {1, 2}}, {E::L2, {2, 0}}};
constexpr FaceInfo faces_q4[] = {{E::L2, {0, 1}}, {E::L2, {1, 2}}, {E::L2, {2, 3}}, {E::L2, {3, 0}}};
constexpr FaceInfo faces_t4[] = {
    {E::T3, {0, 2, 1}}, {E::T3, {0, 1, 3}}, {E::T3, {0, 3, 2}}, {E::T3, {1, 2, 3}}};
constexpr FaceInfo faces_h8[] = {{E::Q4, {0, 3, 2, 1}}, {E::Q4, {4, 5, 6, 7}}, {E::Q4, {0, 1, 5, 4}},
                                 {E::Q4, {1, 2, 6, 5}}, {E::Q4, {2, 3, 7, 6}}, {E::Q4, {3, 0, 4, 7}}};

const ElementInfo table[element_type_count] = {
    {E::L2, "L2", 1, 2, 2, 1, 3, {}, rule_l2, {0, 0, 0}, {1, 0}},
    {E::T3, "T3", 2, 3, 3, 2, 5, faces_t3, rule_t3, {1.0 / 3, 1.0 / 3, 0}, {0, 2, 1}},
    {E::Q4, "Q4", 2, 4, 4, 3, 9, faces_q4, rule_q4, {0, 0, 0}, {0, 3, 2, 1}},
    {E::T4, "T4", 3, 4, 4, 4, 10, faces_t4, rule_t4, {0.25, 0.25, 0.25}, {0, 2, 1, 3}},
    {E::H8, "H8", 3, 8, 8, 5, 12, faces_h8, rule_h8, {0, 0, 0}, {0, 3, 2, 1, 4, 7, 6, 5}},
};

// Corner signs of Q4 and H8 nodes in reference coordinates.
constexpr double sq[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
constexpr double sh[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                             {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};

}  // namespace

const ElementInfo& element_info(ElementType type) { return table[static_cast<int>(type)]; }

void reverse_orientation(ElementType type, std::span<int> nodes) {
  const ElementInfo& info = element_info(type);
  int copy[27];
  for (int a = 0; a < info.nodes; ++a) copy[a] = nodes[a];
  for (int a = 0; a < info.nodes; ++a) nodes[a] = copy[info.mirror[a]];
}

bool element_type_from_gmsh(int gmsh_type, ElementType& type) {
  for (const ElementInfo& e : table)
    if (e.gmsh_type == gmsh_type) {
      type = e.type;
      return true;
    }
  return false;
}

void shape_functions(ElementType type, const double* xi, double* N) {
  switch (type) {
    case E::L2:
      N[0] = 0.5 * (1 - xi[0]);
      N[1] = 0.5 * (1 + xi[0]);
      return;
    case E::T3:
      N[0] = 1 - xi[0] - xi[1];
      N[1] = xi[0];
      N[2] = xi[1];
      return;
    case E::Q4:
      for (int i = 0; i < 4; ++i) N[i] = 0.25 * (1 + sq[i][0] * xi[0]) * (1 + sq[i][1] * xi[1]);
      return;
    case E::T4:
      N[0] = 1 - xi[0] - xi[1] - xi[2];
      N[1] = xi[0];
      N[2] = xi[1];
      N[3] = xi[2];
      return;
    case E::H8:
      for (int i = 0; i < 8; ++i)
        N[i] = 0.125 * (1 + sh[i][0] * xi[0]) * (1 + sh[i][1] * xi[1]) * (1 + sh[i][2] * xi[2]);
      return;
  }
  throw std::logic_error("shape_functions: unknown element type");
}

void shape_derivatives(ElementType type, const double* xi, double* dN) {
  switch (type) {
    case E::L2:
      dN[0] = -0.5;
      dN[1] = 0.5;
      return;
    case E::T3: {
      constexpr double d[6] = {-1, -1, 1, 0, 0, 1};
      for (int i = 0; i < 6; ++i) dN[i] = d[i];
      return;
    }
    case E::Q4:
      for (int i = 0; i < 4; ++i) {
        dN[2 * i] = 0.25 * sq[i][0] * (1 + sq[i][1] * xi[1]);
        dN[2 * i + 1] = 0.25 * sq[i][1] * (1 + sq[i][0] * xi[0]);
      }
      return;
    case E::T4: {
      constexpr double d[12] = {-1, -1, -1, 1, 0, 0, 0, 1, 0, 0, 0, 1};
      for (int i = 0; i < 12; ++i) dN[i] = d[i];
      return;
    }
    case E::H8:
      for (int i = 0; i < 8; ++i) {
        const double a = 1 + sh[i][0] * xi[0], b = 1 + sh[i][1] * xi[1], c = 1 + sh[i][2] * xi[2];
        dN[3 * i] = 0.125 * sh[i][0] * b * c;
        dN[3 * i + 1] = 0.125 * sh[i][1] * a * c;
        dN[3 * i + 2] = 0.125 * sh[i][2] * a * b;
      }
      return;
  }
  throw std::logic_error("shape_derivatives: unknown element type");
}

}  // namespace moreau::fem
