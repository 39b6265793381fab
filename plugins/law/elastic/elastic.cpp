// `elastic`: linear elastic repulsion (LMGC90's ELASTIC_REPELL_CLB; docs/laws.md). Instead
// of rigid unilaterality the contact pushes back with k times its overlap at the end of
// the step, r_n/h = k max(0, −(g + θh u_n)), and Coulomb friction on that force. The
// solver sees it as a compliance on the normal, s_n = g/(θh) and κ_n = 1/(kθh²): where
// the contact pushes, u_n + s_n = −κ_n r_n (every solver takes it unchanged).
#include <moreau/coulomb_law.hpp>

namespace {

using namespace moreau;

class Elastic : public Law {
 public:
  static Schema schema() {
    Schema s;
    s.number("stiffness", "normal stiffness k of each contact point (2D: per unit thickness)").units("N/m").gt(0);
    s.number("friction", "Coulomb friction mu (the dynamic one when static_friction is given)").min(0).fallback(0.0);
    s.number("static_friction", "static friction mu_s >= friction (default: friction)").min(0).optional();
    return s;
  }
  static constexpr const char* doc = "linear elastic repulsion (penalty) with Coulomb friction";

  Elastic(const Params& p, const BuildContext&)
      : k_(p.number("stiffness")), mu_(p.number("friction")),
        mu_s_(p.has("static_friction") ? p.number("static_friction") : mu_) {
    if (mu_s_ < mu_)
      throw p.error("static_friction", "expected a static friction coefficient at least the friction " + number_text(mu_) +
                                           ", got " + number_text(mu_s_));
  }

  void terms(const LawInput& in, const LawVariables&, LawTerms& out) const override {
    out.friction = coulomb::friction(in, mu_s_, mu_);
    out.shift[0] = in.gap / (in.theta * in.h);
    out.compliance[0] = 1 / (k_ * in.theta * in.h * in.h);
  }

 private:
  double k_, mu_, mu_s_;
};

MOREAU_REGISTER(Elastic, "elastic")

}  // namespace

MOREAU_PLUGIN_LIBRARY("moreau_law_elastic")
