// `slip_weakening`: Coulomb friction whose coefficient falls linearly from μ_s to μ_d as
// the contact accumulates slip s over a distance d_c (a slip-weakening fault or joint):
//
//     μ(s) = μ_s − (μ_s − μ_d) min(1, s / d_c).
//
// An example of a third-party contact law with an internal variable (sdk/README.md,
// "Writing a law"): `slip` is a field of the kernel's `contacts` set, so it follows the
// contact from step to step, is written in every output frame (/frames/N/contacts/slip)
// and restored on restart. The law reads the slip at the start of the step (μ is explicit
// in s: one step's lag) and, after the solve, adds the step's slip to it.
#include <cmath>
#include <moreau/coulomb_law.hpp>

namespace {

using namespace moreau;

class SlipWeakening : public Law {
 public:
  static Schema schema() {
    Schema s;
    s.number("static_friction", "mu_s: the friction of a contact that has not slipped").min(0);
    s.number("friction", "mu_d: the friction after a slip of weakening_distance").min(0);
    s.number("weakening_distance", "d_c: the slip over which mu falls from mu_s to mu_d").units("m").gt(0);
    return s;
  }
  static constexpr const char* doc = "Coulomb friction weakening linearly with the accumulated slip (SDK example)";

  SlipWeakening(const Params& p, const BuildContext&)
      : mu_s_(p.number("static_friction")), mu_d_(p.number("friction")), dc_(p.number("weakening_distance")) {
    if (mu_s_ < mu_d_)  // checks the schema cannot express: the JSON pointer and what is expected (exit code 2)
      throw p.error("static_friction", "expected at least friction " + number_text(mu_d_) + ", got " + number_text(mu_s_));
  }

  // One internal variable: the accumulated slip, 1 component in 2D and 3D, written in the
  // frames and restored on restart (the kernel completes set, depths and persistence).
  std::vector<FieldSpec> fields(int) const override {
    return {field_spec(sets::contacts, "slip", 1, 1, 2, "m", FieldOutput::frame, true,
                       "slip accumulated by the contact (slip_weakening)")};
  }
  // update() after each solve; no need to solve the step again (μ uses the start-of-step slip).
  LawNeeds needs() const override { return {.update = true, .iterate = false}; }

  void terms(const LawInput& in, const LawVariables& v, LawTerms& out) const override {
    out.friction = mu_s_ - (mu_s_ - mu_d_) * std::min(1.0, v.begin(0) / dc_);
    out.shift[0] = coulomb::inelastic_shift(in);  // unilateral, inelastic (IQS_CLB)
  }

  bool update(const LawInput& in, const LawResult& r, const LawVariables& v) const override {
    // A closed contact slips by h [(1−θ)‖u_t⁻‖ + θ‖u_t⁺‖] over the step (the positions' rule).
    double before = 0, after = 0;
    for (int k = 1; k < in.dim; ++k) {
      before += in.velocity_begin[k] * in.velocity_begin[k];
      after += r.velocity[k] * r.velocity[k];
    }
    const double step_slip = in.h * ((1 - in.theta) * std::sqrt(before) + in.theta * std::sqrt(after));
    v.end(0) = v.begin(0) + (r.status != 0 ? step_slip : 0.0);
    return true;
  }

 private:
  double mu_s_, mu_d_, dc_;
};

MOREAU_REGISTER(SlipWeakening, "slip_weakening")

}  // namespace

MOREAU_PLUGIN_LIBRARY("moreau_law_slip_weakening")
