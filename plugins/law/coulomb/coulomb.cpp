// `coulomb`: unilateral contact with Coulomb friction (docs/laws.md); inelastic (e = 0,
// LMGC90's IQS_CLB) or with Newton's restitution (e > 0, RST_CLB); with a static friction
// coefficient, μ_s until the contact slides and μ_d while it slides (IQS_DS_CLB).
// μ = 0 is frictionless: the solvers then skip the tangential part.
#include <moreau/coulomb_law.hpp>

namespace {

class Coulomb : public moreau::Law {
 public:
  static moreau::Schema schema() {
    moreau::Schema s;
    s.number("friction", "Coulomb friction coefficient mu (the dynamic one when static_friction is given)").min(0).fallback(0.0);
    s.number("static_friction", "static friction coefficient mu_s >= friction: until the contact slides (default: friction)")
        .min(0).optional();
    s.number("restitution", "Newton normal restitution e (0: inelastic)").min(0).max(1).fallback(0.0);
    return s;
  }
  static constexpr const char* doc = "unilateral contact with Coulomb friction (static/dynamic) and Newton restitution";

  Coulomb(const moreau::Params& p, const moreau::BuildContext&)
      : mu_(p.number("friction")), mu_s_(p.has("static_friction") ? p.number("static_friction") : mu_),
        e_(p.number("restitution")) {
    if (mu_s_ < mu_)
      throw p.error("static_friction", "expected a static friction coefficient at least the (dynamic) friction " +
                                           moreau::number_text(mu_) + ", got " + moreau::number_text(mu_s_));
  }

  void terms(const moreau::LawInput& in, const moreau::LawVariables&, moreau::LawTerms& out) const override {
    out.friction = moreau::coulomb::friction(in, mu_s_, mu_);
    out.shift[0] = moreau::coulomb::restitution_shift(in, e_);
  }

 private:
  double mu_, mu_s_, e_;
};

MOREAU_REGISTER(Coulomb, "coulomb")

}  // namespace

MOREAU_PLUGIN_LIBRARY("moreau_law_coulomb")
