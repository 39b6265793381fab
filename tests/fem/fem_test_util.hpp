#pragma once
// Helpers shared by the finite-element tests.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "elasticity.hpp"
#include "mesh.hpp"
#include "mesh_generate.hpp"

namespace moreau::fem::test {

/// Moves the nodes that are not on the boundary by a deterministic pseudo-random amount of
/// at most `fraction` of `size` per component, so elements become irregular.
inline void distort_interior(Mesh& mesh, double size, double fraction) {
  const std::vector<int>& boundary = mesh.node_set("boundary");
  std::vector<char> on_boundary(mesh.node_count(), 0);
  for (int n : boundary) on_boundary[n] = 1;
  for (int n = 0; n < mesh.node_count(); ++n) {
    if (on_boundary[n]) continue;
    for (int k = 0; k < mesh.dim; ++k)
      mesh.x(k, n) += fraction * size * std::sin(12.9898 * (n + 1) + 78.233 * (k + 1) + 37.719 * n * k);
  }
}

inline Material steel(Hypothesis hypothesis) { return {200e9, 0.3, 7800, hypothesis}; }

inline const char* hypothesis_name(Hypothesis h) {
  return h == Hypothesis::plane_strain ? "plane strain" : h == Hypothesis::plane_stress ? "plane stress" : "3D";
}

/// Observed order of convergence between two errors at sizes h and h/2.
inline double order(double coarse, double fine) { return std::log2(coarse / fine); }

/// A mesh of one element of the given type, positively oriented, slightly irregular.
inline Mesh one_element(ElementType type) {
  Mesh m;
  m.source = "one-element";
  switch (type) {
    case ElementType::T3:
      m.dim = 2;
      m.x.resize(2, 3);
      m.x << 0.1, 1.2, 0.3, -0.1, 0.2, 0.9;
      break;
    case ElementType::Q4:
      m.dim = 2;
      m.x.resize(2, 4);
      m.x << 0.0, 1.1, 1.3, -0.1, 0.0, -0.1, 1.0, 0.8;
      break;
    case ElementType::T4:
      m.dim = 3;
      m.x.resize(3, 4);
      m.x << 0.0, 1.0, 0.1, 0.2, 0.0, 0.1, 1.1, 0.1, 0.0, 0.0, 0.2, 0.9;
      break;
    case ElementType::H8:
      m.dim = 3;
      m.x.resize(3, 8);
      m.x << 0, 1, 1.1, 0, 0.1, 1, 1, -0.1,  //
          0, 0, 1, 1.2, 0, 0.1, 1, 1,        //
          0, 0.1, 0, 0, 1, 1, 1.1, 0.9;
      break;
    default:
      throw std::logic_error("one_element: not a volume type");
  }
  std::vector<int> nodes(m.x.cols());
  for (std::size_t i = 0; i < nodes.size(); ++i) nodes[i] = static_cast<int>(i);
  m.elements.add(type, nodes);
  return m;
}

inline std::vector<ElementType> volume_types() {
  return {ElementType::T3, ElementType::Q4, ElementType::T4, ElementType::H8};
}

}  // namespace moreau::fem::test
