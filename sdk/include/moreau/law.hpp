#pragma once
// A contact law (docs/laws.md): what the solver needs of each contact besides geometry,
// and what a contact remembers from one step to the next.
//
// The solver always sees a Signorini–Coulomb problem (DESIGN §1). A law reaches it by a
// change of variables it chooses per contact and per step (local vectors, normal first;
// r the impulse over the step, u the relative velocity at the end of the step):
//
//     u' = u + s + κ∘r,      r' = r + c e_n,
//     r' ∈ K_μ,   u' + μ‖u'_T‖ e_n ∈ K*_μ,   r' ⊥ u' + μ‖u'_T‖ e_n
//
//  - s, the shift (m/s): max(0, g)/h for the inelastic law (LMGC90 IQS_CLB, g the gap at
//    the detection configuration q⁻ + (1−θ)h v⁻, from which bodies move by θh v⁺: an
//    approaching contact ends the step at (1−θ)g and its next predicted gap is 0, so a
//    resting contact neither drifts into its partner nor is pushed apart); e·u_n⁻ at an
//    impact with Newton restitution (RST_CLB); the stretch of an elastic interface over θh;
//  - c, the cohesion (N s, ≥ 0): the cone's apex moves to r_n = −c, so the contact carries
//    a tension up to c/h and ‖r_t‖ ≤ μ (r_n + c) (Mohr–Coulomb; LMGC90 IQS_MOHR_DS_CLB);
//  - κ, the compliance (m/s per N s, ≥ 0, per component): where the contact is active,
//    u + s = −κ r, an elastic interface (LMGC90 ELASTIC_REPELL_CLB, cohesive zones): a
//    spring of stiffness k on the end-of-step gap g + θh u_n gives s = g/(θh), κ = 1/(kθh²);
//  - μ ≥ 0, chosen each step (static or dynamic friction from the contact's history).
//
// The kernel hands the solver q' = q + s − W' c e_n with W' = W + diag(κ) and turns the
// answer back (r = r' − c e_n, u = u' − s − κ∘r), so every solver, `auto` included, and the
// error measure handle every law unchanged (docs/laws.md says what each law uses).
//
// Internal variables are fields of the kernel's `contacts` set that the law declares
// (fields()): they follow the contact's identity from step to step, are written in every
// output frame and restored on restart. terms() reads their current end-of-step values
// (equal to the start-of-step ones before the first solve of a step) and may write them;
// update(), after each solve, writes their end-of-step values from the contact's result.
// A law whose update changes what terms() gives (damage, a bond breaking) asks for the
// step to be solved again until its variables and the solution agree (LawNeeds::iterate).
#include <cstddef>
#include <moreau/plugin.hpp>
#include <moreau/state.hpp>
#include <vector>

namespace moreau {

struct LawInput {
  double gap = 0;           ///< signed gap at the detection configuration (m)
  double normal_velocity_begin = 0;  ///< u_n⁻: relative normal velocity at the start of the step (m/s)
  double h = 0;             ///< time step (s)
  double theta = 0.5;       ///< θ of the time-stepping scheme (positions move by h[(1−θ)v⁻ + θv⁺])
  /// u_n^free: relative normal velocity of the free velocities (v⁻ plus the smooth forces'
  /// impulse over the step, no contact), m/s; u_n^free − u_n⁻ is what those forces add.
  double normal_velocity_free = 0;
  int dim = 3;                            ///< 2 or 3: components of local vectors
  const double* velocity_begin = nullptr; ///< u⁻, `dim` values, normal first (m/s)
  /// The contact's status at the end of the previous step: 0 open (or new), 1 sticking, 2 sliding.
  int status_begin = 0;
  bool new_contact = true;  ///< the contact did not exist at the previous step
  long step = 0;            ///< index of the step (0: the first step of the run)
};

/// What the solver sees of one contact this step (see the top of this file).
struct LawTerms {
  double friction = 0;                  ///< μ ≥ 0
  double shift[3] = {0, 0, 0};          ///< s, m/s, normal first
  double cohesion = 0;                  ///< c ≥ 0, N s: r_n + c ≥ 0
  double compliance[3] = {0, 0, 0};     ///< κ ≥ 0, (m/s)/(N s), normal first
};

/// The contact's result after a solve, in true variables.
struct LawResult {
  const double* impulse = nullptr;   ///< r, `dim` values, N s (the force is r/h)
  const double* velocity = nullptr;  ///< u at the end of the step, `dim` values, m/s
  int status = 0;                    ///< 0 open, 1 sticking, 2 sliding (in the solver's variables r', u')
};

/// What the kernel must do for a law.
struct LawNeeds {
  bool update = false;   ///< call update() after each solve (a law with internal variables)
  /// Solve the step again while update() returns false (internal variables the solution
  /// depends on: damage, bonds that break), at most law_solves_per_step solves a step.
  bool iterate = false;
};

/// The most solves of one step for laws that iterate (a step still inconsistent after
/// them keeps its last solve, and the run warns).
inline constexpr int law_solves_per_step = 50;

/// One contact's internal variables, the law's fields in the order fields() gave them.
/// begin(): at the start of the step (read only); end(): at the end of the step, which
/// the next step starts from (both equal when the step begins; new contacts: zeros).
class LawVariables {
 public:
  LawVariables(const double* const* begin, double* const* end, const int* components, std::size_t row)
      : begin_(begin), end_(end), comps_(components), row_(row) {}
  double begin(int field, int component = 0) const { return begin_[field][row_ * comps_[field] + component]; }
  double& end(int field, int component = 0) const { return end_[field][row_ * comps_[field] + component]; }

 private:
  const double* const* begin_;
  double* const* end_;
  const int* comps_;
  std::size_t row_;
};

class MOREAU_API Law : public Plugin {
 public:
  static constexpr Kind kind = Kind::law;
  /// Its internal variables: fields of the `contacts` set (name, components in 2D and 3D,
  /// units, doc, file type; the kernel sets the set, two depths, persist, restart and frame
  /// output). Laws may share a field by giving the same name and shape (`bond`,
  /// law_fields.hpp). Empty: none.
  virtual std::vector<FieldSpec> fields(int /*dim*/) const { return {}; }
  virtual LawNeeds needs() const { return {}; }
  /// The terms of one contact for this step (called before each solve of the step).
  virtual void terms(const LawInput& in, const LawVariables& v, LawTerms& out) const = 0;
  /// After each solve (when needs().update): the contact's end-of-step internal variables
  /// from its result. Returns false when they differ from those terms() used for this
  /// solve enough to change the solution (the step is then solved again, when
  /// needs().iterate); true otherwise.
  virtual bool update(const LawInput& /*in*/, const LawResult& /*result*/, const LawVariables& /*v*/) const {
    return true;
  }
  /// The largest gap (m) at which the law acts on an open contact (a meniscus); the
  /// scene's detection.alert must reach it. 0: only touching contacts matter.
  virtual double range() const { return 0; }
};

}  // namespace moreau
