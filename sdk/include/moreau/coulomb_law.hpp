#pragma once
// The pieces of LMGC90's Coulomb laws that every law here shares (docs/laws.md): the
// normal shift of the inelastic law and of Newton restitution, and static/dynamic
// friction chosen from the contact's history. For third-party laws too.
#include <algorithm>
#include <cstdio>
#include <moreau/law.hpp>
#include <string>

namespace moreau {
/// A number as messages print it (6 significant digits), for laws' parameter errors.
inline std::string number_text(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", x);
  return buf;
}
}  // namespace moreau

namespace moreau::coulomb {

/// Inelastic (IQS_CLB): s_n = max(0, g)/h.
inline double inelastic_shift(const LawInput& in) { return std::max(0.0, in.gap) / in.h; }

/// Newton restitution e (RST_CLB) for a contact that is closed or closes within the step
/// (an impact), the inelastic shift otherwise. u_n⁺ ≥ −e u_n⁻ alone gains
/// (θ(1+e) − 1) h a_n u_n⁻ at an impact when θ(1+e) > 1 (a_n: the smooth forces' normal
/// acceleration; docs/contacts.md): taking c = (θ(1+e) − 1)/e of the smooth forces'
/// velocity change off the target cancels it (c = 0, the plain law, where the scheme
/// already dissipates). Never weaker than the inelastic law, so a slow impact cannot sink.
inline double restitution_shift(const LawInput& in, double e) {
  const double gap_rate = inelastic_shift(in);
  if (e == 0.0) return gap_rate;
  const bool impact = in.normal_velocity_begin < 0 && in.gap + in.h * in.normal_velocity_begin <= 0;
  if (!impact) return gap_rate;
  const double c = std::max(0.0, (in.theta * (1 + e) - 1) / e);
  const double target = e * in.normal_velocity_begin - c * (in.normal_velocity_free - in.normal_velocity_begin);
  return std::min(target, gap_rate);
}

/// Static/dynamic friction (IQS_DS_CLB): μ_d for a contact that was sliding at the end of
/// the previous step, μ_s otherwise (sticking, open or new).
inline double friction(const LawInput& in, double static_mu, double dynamic_mu) {
  return in.status_begin == 2 ? dynamic_mu : static_mu;
}

}  // namespace moreau::coulomb
