#pragma once
// Energies of the rigid bodies from the State: the rows of `rigid.nodes` (other
// modelizations' bodies are not counted). What the example hooks of user/ log and test;
// installed with the SDK, so a hook copied out of user/ builds on its own.
#include <cmath>
#include <moreau/rigid_fields.hpp>
#include <moreau/state.hpp>
#include <vector>

namespace moreau::user {

struct Energies {
  double translational = 0;  ///< Σ ½ m v² (J)
  double rotational = 0;     ///< Σ ½ Ωᵀ I Ω, Ω body-frame angular velocity (J)
  double potential = 0;      ///< Σ −m g·x (J), zero at the origin
  double kinetic() const { return translational + rotational; }
  double total() const { return kinetic() + potential; }
};

/// Values at `depth` (Depth::begin after a step's end, where hooks usually read them).
inline Energies energies(const State& st, const std::vector<double>& g, Depth depth = Depth::begin) {
  namespace R = moreau::rigid;
  Energies e;
  if (!st.has_set(R::nodes)) return e;
  const int d = st.dimension();
  const double* m = st.field(R::nodes, R::mass).data();
  const double* fixed = st.field(R::nodes, R::fixed).data();
  const double* x = st.field(R::nodes, R::position).data(depth);
  const double* v = st.field(R::nodes, R::velocity).data(depth);
  const double* w = st.field(R::nodes, R::angular_velocity).data(depth);
  const double* I = st.field(R::nodes, R::inertia).data();
  for (std::size_t b = 0; b < st.set(R::nodes).rows(); ++b) {
    if (fixed[b] != 0) continue;
    double v2 = 0, gx = 0;
    for (int k = 0; k < d; ++k) {
      v2 += v[b * d + k] * v[b * d + k];
      gx += g[k] * x[b * d + k];
    }
    e.translational += 0.5 * m[b] * v2;
    e.potential -= m[b] * gx;
    if (d == 2) {
      e.rotational += 0.5 * I[b] * w[b] * w[b];
    } else {
      // Ω = Rᵀ ω with R from the unit quaternion (w x y z).
      const double* q = st.field(R::nodes, R::orientation).data(depth) + 4 * b;
      const double* om = w + 3 * b;
      const double qw = q[0], qx = -q[1], qy = -q[2], qz = -q[3];  // conjugate: world → body
      const double t[3] = {2 * (qy * om[2] - qz * om[1]), 2 * (qz * om[0] - qx * om[2]), 2 * (qx * om[1] - qy * om[0])};
      const double W[3] = {om[0] + qw * t[0] + (qy * t[2] - qz * t[1]), om[1] + qw * t[1] + (qz * t[0] - qx * t[2]),
                           om[2] + qw * t[2] + (qx * t[1] - qy * t[0])};
      const double* J = I + 6 * b;  // xx yy zz xy xz yz
      const double IW[3] = {J[0] * W[0] + J[3] * W[1] + J[4] * W[2], J[3] * W[0] + J[1] * W[1] + J[5] * W[2],
                            J[4] * W[0] + J[5] * W[1] + J[2] * W[2]};
      e.rotational += 0.5 * (W[0] * IW[0] + W[1] * IW[1] + W[2] * IW[2]);
    }
  }
  return e;
}

}  // namespace moreau::user
