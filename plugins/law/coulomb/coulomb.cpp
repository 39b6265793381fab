// `coulomb`: unilateral contact with Coulomb friction; inelastic (e = 0, LMGC90's
// IQS_CLB) or with Newton's restitution (e > 0, RST_CLB). μ = 0 is frictionless: the
// solvers then skip the tangential part.
#include <algorithm>
#include <moreau/law.hpp>

namespace {

class Coulomb : public moreau::Law {
 public:
  static moreau::Schema schema() {
    moreau::Schema s;
    s.number("friction", "Coulomb friction coefficient mu").min(0).fallback(0.0);
    s.number("restitution", "Newton normal restitution e (0: inelastic)").min(0).max(1).fallback(0.0);
    return s;
  }
  static constexpr const char* doc = "unilateral contact with Coulomb friction and Newton restitution";

  Coulomb(const moreau::Params& p, const moreau::BuildContext&)
      : mu_(p.number("friction")), e_(p.number("restitution")) {}

  double friction() const override { return mu_; }

  double normal_shift(const moreau::LawInput& in) const override {
    const double gap_rate = std::max(0.0, in.gap) / in.h;
    if (e_ == 0.0) return gap_rate;
    // Impact: the contact is closed, or approaching fast enough to close within the step.
    const bool impact = in.normal_velocity_begin < 0 && in.gap + in.h * in.normal_velocity_begin <= 0;
    return impact ? e_ * in.normal_velocity_begin : gap_rate;
  }

 private:
  double mu_, e_;
};

MOREAU_REGISTER(Coulomb, "coulomb")

}  // namespace

MOREAU_PLUGIN_LIBRARY("moreau_law_coulomb")
