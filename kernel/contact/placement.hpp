#pragma once
// A contactor's placement in its body's frame (scene keys `offset`, `angle` / `orientation`
// of a contactor): several contactors on one body make a cluster. Shapes stay defined in
// their own frame; the kernel composes the body pose with the placement for detection,
// and moves the shapes' mass properties by it to sum a cluster's.
#include <array>
#include <cmath>
#include <moreau/modelization.hpp>

namespace moreau::kernel {

struct Placement {
  std::array<double, 3> offset{0, 0, 0};        ///< body frame, m
  double angle = 0;                             ///< 2D rotation, rad
  std::array<double, 4> orientation{1, 0, 0, 0};  ///< 3D unit quaternion w x y z (shape to body)

  /// Identity placements (the common case) let detection use the body pose as it is.
  bool identity() const {
    return offset[0] == 0 && offset[1] == 0 && offset[2] == 0 && angle == 0 && orientation[0] == 1 &&
           orientation[1] == 0 && orientation[2] == 0 && orientation[3] == 0;
  }
};

/// Hamilton product a ⊗ b (w x y z).
inline void quat_product(const double* a, const double* b, double* out) {
  out[0] = a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3];
  out[1] = a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2];
  out[2] = a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1];
  out[3] = a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0];
}

/// Rotation matrix (row-major) of a 2D angle (about z) or a 3D unit quaternion.
inline std::array<double, 9> rotation_matrix(int dim, double angle, const double* q) {
  if (dim == 2) {
    const double c = std::cos(angle), s = std::sin(angle);
    return {c, -s, 0, s, c, 0, 0, 0, 1};
  }
  const double w = q[0], x = q[1], y = q[2], z = q[3];
  return {1 - 2 * (y * y + z * z), 2 * (x * y - w * z),     2 * (x * z + w * y),
          2 * (x * y + w * z),     1 - 2 * (x * x + z * z), 2 * (y * z - w * x),
          2 * (x * z - w * y),     2 * (y * z + w * x),     1 - 2 * (x * x + y * y)};
}

/// World pose of a contactor: body pose (position 3, rotation 4: 2D angle in [0]) composed
/// with its placement, in the same layout. x = x_b + R_b o, rotation R_b R_c.
inline void compose_pose(int dim, const double* body, const Placement& p, double* out) {
  const auto Rb = rotation_matrix(dim, body[3], body + 3);
  for (int i = 0; i < 3; ++i)
    out[i] = body[i] + Rb[3 * i] * p.offset[0] + Rb[3 * i + 1] * p.offset[1] + Rb[3 * i + 2] * p.offset[2];
  if (dim == 2) {
    out[2] = 0;
    out[3] = body[3] + p.angle;
    out[4] = out[5] = out[6] = 0;
  } else {
    quat_product(body + 3, p.orientation.data(), out + 3);
  }
}

/// A shape's mass properties (in its own frame) moved to its placement in the body frame:
/// centre o + R c, inertia R J Rᵀ (2D: the polar moment does not change).
inline MassProperties place(int dim, const MassProperties& m, const Placement& p) {
  const auto Rc = rotation_matrix(dim, p.angle, p.orientation.data());
  MassProperties out;
  out.volume = m.volume;
  for (int i = 0; i < 3; ++i)
    out.center[i] = p.offset[i] + Rc[3 * i] * m.center[0] + Rc[3 * i + 1] * m.center[1] + Rc[3 * i + 2] * m.center[2];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      double s = 0;
      for (int k = 0; k < 3; ++k)
        for (int l = 0; l < 3; ++l) s += Rc[3 * i + k] * m.inertia[3 * k + l] * Rc[3 * j + l];
      out.inertia[3 * i + j] = s;
    }
  if (dim == 2) out.center[2] = 0;
  return out;
}

}  // namespace moreau::kernel
