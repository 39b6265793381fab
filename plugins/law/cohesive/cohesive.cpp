// `cohesive`: a brittle Mohr–Coulomb bond (LMGC90's IQS_MOHR_DS_CLB; docs/laws.md). Every
// contact present at the first step of the run with a gap up to `bond_gap` is bonded.
// An intact bond carries a tension up to its tensile strength and a shear force up to
// C + μ_s σ_n (per unit of its area), solved as a Coulomb cone of coefficient μ_s whose
// apex is moved to r_n = −C A h/μ_s (a change of variables every solver takes unchanged).
// When the solution reaches the envelope (the apex, the cone, or the tension cut-off),
// the bond breaks for good and the step is solved again without it; the contact is then
// plain Coulomb with static/dynamic friction.
#include <moreau/coulomb_law.hpp>
#include <moreau/law_fields.hpp>

namespace {

using namespace moreau;
namespace LF = moreau::law_fields;

class Cohesive : public Law {
 public:
  static Schema schema() {
    Schema s;
    s.number("tensile_strength", "tensile strength of the bond, sigma_t (at most cohesion / static friction)").units("Pa").gt(0);
    s.number("cohesion", "shear strength of the bond under zero normal stress, C").units("Pa").gt(0);
    s.number("area", "area of the interface each contact point carries (2D: length, per unit thickness)").units("m2").gt(0);
    s.number("friction", "Coulomb friction mu: the bond's envelope slope and, once broken, the (dynamic) friction").gt(0);
    s.number("static_friction", "static friction mu_s >= friction (default: friction): the intact bond's envelope "
                                "slope and, once broken, the friction until the contact slides").gt(0).optional();
    s.number("bond_gap", "contacts at the first step with a gap up to this are bonded").units("m").min(0).fallback(0.0);
    return s;
  }
  static constexpr const char* doc = "brittle Mohr-Coulomb bond (tension and shear strength), then Coulomb friction";

  Cohesive(const Params& p, const BuildContext&)
      : sigma_t_(p.number("tensile_strength")), cohesion_(p.number("cohesion")), area_(p.number("area")),
        mu_(p.number("friction")), mu_s_(p.has("static_friction") ? p.number("static_friction") : mu_),
        bond_gap_(p.number("bond_gap")) {
    if (mu_s_ < mu_)
      throw p.error("static_friction", "expected a static friction coefficient at least the friction " + number_text(mu_) +
                                           ", got " + number_text(mu_s_));
    // The envelope |τ| ≤ C + μ_s σ meets σ = −C/μ_s: a larger tensile strength is never reached.
    if (sigma_t_ > cohesion_ / mu_s_ * (1 + 1e-12))
      throw p.error("tensile_strength", "expected at most cohesion / static friction = " + number_text(cohesion_ / mu_s_) +
                                            " Pa (the apex of the Mohr-Coulomb envelope), got " + number_text(sigma_t_));
  }

  std::vector<FieldSpec> fields(int) const override { return {LF::bond_field()}; }
  LawNeeds needs() const override { return {true, true}; }

  void terms(const LawInput& in, const LawVariables& v, LawTerms& out) const override {
    double& bond = v.end(0);
    if (bond == LF::no_bond && in.step == 0 && in.new_contact && in.gap <= bond_gap_ + 1e-9) bond = LF::intact;
    out.shift[0] = coulomb::inelastic_shift(in);
    if (bond == LF::intact) {
      out.friction = mu_s_;
      out.cohesion = apex(in.h);
    } else {
      out.friction = coulomb::friction(in, mu_s_, mu_);
    }
  }

  bool update(const LawInput& in, const LawResult& res, const LawVariables& v) const override {
    double& bond = v.end(0);
    if (bond != LF::intact) return true;
    // It breaks where the solution reaches its envelope: slipping on the cone (status in
    // the solver's variables r' = r + c e_n), pulled to the apex (r'_n = 0: the tension
    // C/μ_s), or beyond the tension cut-off σ_t. Not merely on the cone while sticking:
    // several bonds of one rigid block share its load in ways the rigid problem leaves
    // open, and one of them may sit on its cone while the block holds.
    const double c = apex(in.h);
    const bool slips = res.status == 2;
    const bool at_apex = res.impulse[0] + c <= 1e-9 * c;
    const bool cut_off = res.impulse[0] <= -sigma_t_ * area_ * in.h * (1 - 1e-9);
    if (!slips && !at_apex && !cut_off) return true;
    bond = LF::broken;
    return false;
  }

 private:
  /// c = C A h / μ_s: the envelope's apex as an impulse.
  double apex(double h) const { return cohesion_ * area_ * h / mu_s_; }
  double sigma_t_, cohesion_, area_, mu_, mu_s_, bond_gap_;
};

MOREAU_REGISTER(Cohesive, "cohesive")

}  // namespace

MOREAU_PLUGIN_LIBRARY("moreau_law_cohesive")
