// `czm`: a cohesive zone with damage (the bilinear MAL_CZM of LMGC90, Monerie–Raous type;
// docs/laws.md). Every contact present at the first step with a gap up to `bond_gap` is a
// bond of area A. While sound it is a linear spring on the opening δ = (δ_n, δ_t), the
// normal opening from the gap at bonding and the tangential one accumulated from the
// relative velocity:
//     T = (1 − D) K δ   (compression, δ_n < 0: undamaged normal stiffness),
// with K = diag(k_n, k_t) A. Damage starts when λ = ‖(⟨δ_n⟩/δ_n0, ‖δ_t‖/δ_t0)‖ reaches 1
// (δ_0 = strength / stiffness: a quadratic interaction of the two strengths) and grows
// with λ so that the traction falls linearly to zero at λ_f, the mixed-mode rule
// G_I/G_Ic + G_II/G_IIc = 1 giving 1/λ_f = a_n²/λ_fn + a_t²/λ_ft (a: the mode mix,
// λ_fi = 2 G_ic k_i / strength_i²). D never decreases; unloading goes back along the
// damaged stiffness. At D = 1 the bond is broken: Coulomb friction from then on.
//
// The solver sees the spring as a compliance on the end-of-step opening (law.hpp):
// s = δ_det/(θh), κ = 1/(k (1−D) A θh²) per component, inside a cone wide enough never to
// bind (apex 2σA h below, slope 2τ/σ). D is the end-of-step damage: the step is solved
// again until it agrees with the opening it produces (a monotone fixed point).
#include <algorithm>
#include <cmath>
#include <moreau/coulomb_law.hpp>
#include <moreau/law_fields.hpp>

namespace {

using namespace moreau;
namespace LF = moreau::law_fields;

enum Var { bond = 0, damage = 1, opening = 2, rest_gap = 3 };

class Czm : public Law {
 public:
  static Schema schema() {
    Schema s;
    s.number("normal_stiffness", "normal stiffness of the interface, k_n").units("Pa/m").gt(0);
    s.number("tangential_stiffness", "tangential stiffness of the interface, k_t").units("Pa/m").gt(0);
    s.number("normal_strength", "tensile strength, sigma_max").units("Pa").gt(0);
    s.number("shear_strength", "shear strength, tau_max").units("Pa").gt(0);
    s.number("mode_I_energy", "fracture energy in opening, G_Ic (at least sigma_max^2 / (2 k_n))").units("J/m2").gt(0);
    s.number("mode_II_energy", "fracture energy in shear, G_IIc (at least tau_max^2 / (2 k_t))").units("J/m2").gt(0);
    s.number("area", "area of the interface each contact point carries (2D: length, per unit thickness)").units("m2").gt(0);
    s.number("friction", "Coulomb friction mu once the bond is broken").min(0).fallback(0.0);
    s.number("bond_gap", "contacts at the first step with a gap up to this are bonded").units("m").min(0).fallback(0.0);
    return s;
  }
  static constexpr const char* doc = "cohesive zone with damage (bilinear, mixed mode), then Coulomb friction";

  Czm(const Params& p, const BuildContext&)
      : kn_(p.number("normal_stiffness")), kt_(p.number("tangential_stiffness")), sn_(p.number("normal_strength")),
        st_(p.number("shear_strength")), gn_(p.number("mode_I_energy")), gt_(p.number("mode_II_energy")),
        area_(p.number("area")), mu_(p.number("friction")), bond_gap_(p.number("bond_gap")) {
    // δ_f = 2G/σ must not come before δ_0 = σ/k: the softening branch would turn back.
    if (gn_ < sn_ * sn_ / (2 * kn_) * (1 - 1e-12))
      throw p.error("mode_I_energy", "expected at least normal_strength^2 / (2 normal_stiffness) = " +
                                         number_text(sn_ * sn_ / (2 * kn_)) + " J/m2 (the elastic energy at the strength), got " +
                                         number_text(gn_));
    if (gt_ < st_ * st_ / (2 * kt_) * (1 - 1e-12))
      throw p.error("mode_II_energy", "expected at least shear_strength^2 / (2 tangential_stiffness) = " +
                                          number_text(st_ * st_ / (2 * kt_)) + " J/m2 (the elastic energy at the strength), got " +
                                          number_text(gt_));
    dn0_ = sn_ / kn_;
    dt0_ = st_ / kt_;
    lfn_ = std::max(1.0, 2 * gn_ * kn_ / (sn_ * sn_));
    lft_ = std::max(1.0, 2 * gt_ * kt_ / (st_ * st_));
  }

  std::vector<FieldSpec> fields(int) const override {
    return {LF::bond_field(),
            field_spec(sets::contacts, LF::damage, 1, 1, 2, "1", FieldOutput::frame, true,
                       "damage of the cohesive zone: 0 sound, 1 broken"),
            field_spec(sets::contacts, "opening", 2, 3, 2, "m", FieldOutput::frame, true,
                       "opening of the cohesive zone at the end of the step, local (normal, then tangential)"),
            field_spec(sets::contacts, "rest_gap", 1, 1, 2, "m", FieldOutput::frame, true,
                       "gap of the contact when it was bonded (zero opening)")};
  }
  LawNeeds needs() const override { return {true, true}; }
  /// A bond stays a contact (so a bond) only while detected: up to the rupture opening.
  double range() const override { return dn0_ * lfn_; }

  void terms(const LawInput& in, const LawVariables& v, LawTerms& out) const override {
    double& b = v.end(bond);
    if (b == LF::no_bond && in.step == 0 && in.new_contact && in.gap <= bond_gap_ + 1e-9) {
      b = LF::intact;
      v.end(rest_gap) = in.gap;
    }
    if (b != LF::intact) {
      out.friction = mu_;
      out.shift[0] = coulomb::inelastic_shift(in);
      return;
    }
    double det[3];
    detection_opening(in, v, det);
    const double sound = 1 - v.end(damage), th2 = in.theta * in.h * in.h;
    const double kn = (det[0] > 0 ? sound : 1.0) * kn_ * area_, kt = sound * kt_ * area_;
    for (int k = 0; k < in.dim; ++k) out.shift[k] = det[k] / (in.theta * in.h);
    out.compliance[0] = 1 / (kn * th2);
    for (int k = 1; k < in.dim; ++k) out.compliance[k] = 1 / (kt * th2);
    // A cone that never binds at a consistent state: tension ≤ σA, shear ≤ τA.
    out.cohesion = 2 * sn_ * area_ * in.h;
    out.friction = 2 * st_ / sn_;
  }

  bool update(const LawInput& in, const LawResult& res, const LawVariables& v) const override {
    if (v.end(bond) == LF::no_bond) return true;
    // The end-of-step opening: from the detection configuration by θh u⁺.
    double det[3], end[3];
    detection_opening(in, v, det);
    for (int k = 0; k < in.dim; ++k) {
      end[k] = det[k] + in.theta * in.h * res.velocity[k];
      v.end(opening, k) = end[k];
    }
    if (v.end(bond) == LF::broken) return true;
    const double before = v.end(damage);
    double d = std::max(v.begin(damage), damage_at(in.dim, end));
    if (d >= 1 - 1e-9) {
      d = 1;
      v.end(bond) = LF::broken;
    }
    v.end(damage) = d;
    return std::fabs(d - before) <= 1e-12;
  }

 private:
  /// The opening at the detection configuration: normal from the gap, tangential from
  /// the end of the previous step by (1−θ)h u_t⁻.
  void detection_opening(const LawInput& in, const LawVariables& v, double* det) const {
    det[0] = in.gap - v.end(rest_gap);
    for (int k = 1; k < in.dim; ++k) det[k] = v.begin(opening, k) + (1 - in.theta) * in.h * in.velocity_begin[k];
  }

  /// D for an opening (bilinear in λ, with the mixed-mode λ_f).
  double damage_at(int dim, const double* delta) const {
    double t = 0;
    for (int k = 1; k < dim; ++k) t += delta[k] * delta[k];
    const double an = std::max(0.0, delta[0]) / dn0_, at = std::sqrt(t) / dt0_;
    const double lambda = std::hypot(an, at);
    if (lambda <= 1) return 0;
    const double mn = an / lambda, mt = at / lambda;
    const double lf = 1 / (mn * mn / lfn_ + mt * mt / lft_);
    if (lambda >= lf) return 1;
    return lf * (lambda - 1) / (lambda * (lf - 1));
  }

  double kn_, kt_, sn_, st_, gn_, gt_, area_, mu_, bond_gap_;
  double dn0_, dt0_, lfn_, lft_;
};

MOREAU_REGISTER(Czm, "czm")

}  // namespace

MOREAU_PLUGIN_LIBRARY("moreau_law_czm")
