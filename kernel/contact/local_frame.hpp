#pragma once
// The local frame of a contact: normal n first, then tangents (t in 2D; t, s in 3D),
// built deterministically from n alone so that a persisting contact keeps its frame
// (and its warm-start impulse keeps its meaning) from step to step.
#include <array>
#include <cmath>

namespace moreau::kernel {

/// Rows of the frame, each a unit vector in world coordinates: frame[0] = n.
using Frame3 = std::array<std::array<double, 3>, 3>;

inline Frame3 local_frame_3d(const double n[3]) {
  Frame3 f{};
  f[0] = {n[0], n[1], n[2]};
  // t: n × (the world axis least aligned with n), normalised; s = n × t.
  double a[3] = {0, 0, 0};
  const double ax = std::fabs(n[0]), ay = std::fabs(n[1]), az = std::fabs(n[2]);
  if (ax <= ay && ax <= az) a[0] = 1;
  else if (ay <= az) a[1] = 1;
  else a[2] = 1;
  double t[3] = {n[1] * a[2] - n[2] * a[1], n[2] * a[0] - n[0] * a[2], n[0] * a[1] - n[1] * a[0]};
  const double l = std::sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]);
  for (double& x : t) x /= l;
  f[1] = {t[0], t[1], t[2]};
  f[2] = {n[1] * t[2] - n[2] * t[1], n[2] * t[0] - n[0] * t[2], n[0] * t[1] - n[1] * t[0]};
  return f;
}

/// 2D: t is n turned by +90°.
inline std::array<std::array<double, 2>, 2> local_frame_2d(const double n[2]) {
  return {{{n[0], n[1]}, {-n[1], n[0]}}};
}

}  // namespace moreau::kernel
