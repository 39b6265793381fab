// `wet`: capillary cohesion (LMGC90's IQS_WET_DS_CLB family; docs/laws.md). A liquid bridge
// forms when two grains touch (and, at the first step of the run, between grains already
// within `rupture_distance`: a wet packing); while it lasts it pulls with up to the
// constant `adhesion` force: r_n + F h ≥ 0 and ‖r_t‖ ≤ μ (r_n + F h), a Coulomb cone with
// its apex moved (a change of variables every solver takes unchanged). It ruptures when
// the gap exceeds `rupture_distance` and forms again at the next touch. No memory beyond
// the bridge itself (`bond`: 1 bridge, 2 ruptured).
#include <moreau/coulomb_law.hpp>
#include <moreau/law_fields.hpp>

namespace {

using namespace moreau;
namespace LF = moreau::law_fields;

class Wet : public Law {
 public:
  static Schema schema() {
    Schema s;
    s.number("adhesion", "capillary force of a bridge, F (2D: per unit thickness)").units("N").gt(0);
    s.number("rupture_distance", "gap beyond which a bridge breaks (at most the detection alert distance)").units("m").gt(0);
    s.number("friction", "Coulomb friction mu (the dynamic one when static_friction is given)").min(0).fallback(0.0);
    s.number("static_friction", "static friction mu_s >= friction (default: friction)").min(0).optional();
    return s;
  }
  static constexpr const char* doc = "capillary bridges: constant adhesion within a rupture distance, Coulomb friction";

  Wet(const Params& p, const BuildContext&)
      : force_(p.number("adhesion")), distance_(p.number("rupture_distance")), mu_(p.number("friction")),
        mu_s_(p.has("static_friction") ? p.number("static_friction") : mu_) {
    if (mu_s_ < mu_)
      throw p.error("static_friction", "expected a static friction coefficient at least the friction " + number_text(mu_) +
                                           ", got " + number_text(mu_s_));
  }

  std::vector<FieldSpec> fields(int) const override { return {LF::bond_field()}; }
  double range() const override { return distance_; }

  void terms(const LawInput& in, const LawVariables& v, LawTerms& out) const override {
    double& bridge = v.end(0);
    if (bridge == LF::intact && in.gap > distance_) bridge = LF::broken;
    else if (bridge != LF::intact && (in.gap <= 1e-9 || (in.step == 0 && in.new_contact && in.gap <= distance_)))
      bridge = LF::intact;
    out.friction = coulomb::friction(in, mu_s_, mu_);
    out.shift[0] = coulomb::inelastic_shift(in);
    if (bridge == LF::intact) out.cohesion = force_ * in.h;
  }

 private:
  double force_, distance_, mu_, mu_s_;
};

MOREAU_REGISTER(Wet, "wet")

}  // namespace

MOREAU_PLUGIN_LIBRARY("moreau_law_wet")
