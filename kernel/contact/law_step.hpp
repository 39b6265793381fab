#pragma once
// The contact laws' part of a step (law.hpp, docs/laws.md): each law's terms turned into
// the standard Coulomb problem every solver reads, the answer turned back, the laws'
// internal variables (fields of the `contacts` set) updated after each solve, and the
// step solved again while a law that iterates is not consistent with the solution. Also
// the bond counts of the `laws` set. Kept apart from contact_stages.cpp, which only calls
// it around the solve.
//
// Change of variables, per contact (law.hpp): the solver sees r' = r + c e_n and
//   u' = W' r' + q',  W' = W + diag(κ),  q' = q_free + s − W' c e_n,
// so u' = u + s + κ∘r with u = W r + q_free the true velocity. W' is the assembled W with
// κ added on its diagonal (entries made for every row the first time some κ ≠ 0) and,
// with the factored form, BodyFactor::diagonal = κ; W' c e_n goes through whichever the
// solver has (W, or the factor's product).
#include <Eigen/Core>
#include <cstddef>
#include <moreau/contact_problem.hpp>
#include <moreau/law.hpp>
#include <moreau/state.hpp>
#include <string>
#include <vector>

#include "../plugin/owned.hpp"

namespace moreau::kernel {

class LawStep {
 public:
  /// At build: declares each law's internal variables on the `contacts` set (and the
  /// `laws` set of counts when a law has bonds). `names`, `pointers`: the scene's law
  /// names and their JSON pointers (for errors), in the order of `laws`.
  void setup(State& state, const std::vector<Owned<Law>>& laws, const std::vector<std::string>& names,
             const std::vector<std::string>& pointers);
  bool iterates() const { return iterate_; }
  /// Whether some law (or law `l`) keeps per-contact variables.
  bool keeps_variables() const { return variables_; }
  bool keeps_variables(int l) const { return !fields_[static_cast<std::size_t>(l)].names.empty(); }

  /// Per step, before the first solve: each contact's law, gap, u⁻ (dim each), normal
  /// free velocity, whether it is new; the status it ended the previous step with is read
  /// from the `contacts` set (persistent).
  void begin(State& state, long step, double h, double theta, const std::vector<int>& law,
             const std::vector<double>& gap, const Eigen::VectorXd& u_begin, const Eigen::VectorXd& q_free,
             const std::vector<char>& new_contact);
  /// Before a solve: the laws' terms (from the current internal variables), written into
  /// the problem (μ, q', κ in W and the factor) and r turned into r' (r: the true impulses,
  /// a warm start). The problem's W or factor must be in place.
  void to_solver(LocalProblem& problem, Eigen::VectorXd& r);
  /// Per step, before to_solver: the largest normal shift each contact may have (+∞: any),
  /// which to_solver takes when the law's is larger (swept contacts, swept_detection.hpp);
  /// null: none. The contact where a cap bit most, and the law's shift there, are kept.
  void cap_normal_shift(const std::vector<double>* caps) {
    caps_ = caps;
    capped_ = -1;
  }
  /// The contact whose law's normal shift was capped most this step (−1: none), its law's shift.
  long capped() const { return capped_; }
  double capped_law_shift() const { return capped_law_shift_; }
  /// After a solve: r', u' kept for the status, r and u made true. `error`: the error
  /// the solve reached (DESIGN §1, relative to error_denominator): a contact on its cone
  /// slides only if its slip exceeds what that error leaves unresolved.
  void from_solver(const LocalProblem& problem, Eigen::VectorXd& r, Eigen::VectorXd& u, double error);
  /// The laws' updates from (r, u); true when another solve is needed (a law that iterates
  /// is not consistent yet).
  bool update(const Eigen::VectorXd& r, const Eigen::VectorXd& u);
  /// After the last solve: bond counts of the step.
  void finish(State& state);
  /// A step without contacts: no intact bonds.
  void no_contacts(State& state);

  /// Status of contact a from the last solve: 0 open, 1 sticking, 2 sliding (in r', u').
  int status(std::size_t a) const { return status_[a]; }
  /// The last solve's answer in the solver's variables r', u'.
  const Eigen::VectorXd& solver_impulse() const { return r_solver_; }
  const Eigen::VectorXd& solver_velocity() const { return u_solver_; }

 private:
  struct LawFields {
    std::vector<std::string> names;
    std::vector<const double*> begin;
    std::vector<double*> end;
    std::vector<int> components;
  };
  LawVariables variables(std::size_t a) const;
  void set_compliance(LocalProblem& problem);

  const std::vector<Owned<Law>>* laws_ = nullptr;
  std::vector<LawNeeds> needs_;
  std::vector<LawFields> fields_;
  bool update_ = false, iterate_ = false, variables_ = false;
  bool counts_ = false;  ///< some law declares `bond`: the `laws` set exists

  // The step's contacts.
  int d_ = 3;
  std::size_t nc_ = 0;
  std::vector<LawInput> in_;
  const std::vector<int>* law_ = nullptr;
  const Eigen::VectorXd* q_free_ = nullptr;
  const Eigen::VectorXd* u_begin_ = nullptr;
  Eigen::VectorXd shift_, cohesion_, compliance_;  ///< this solve's terms: s (d·nc), c e_n (d·nc), κ (d·nc)
  bool any_cohesion_ = false, any_compliance_ = false;
  Eigen::VectorXd r_solver_, u_solver_, scratch_;
  std::vector<double> product_impulse_, product_dv_;
  std::vector<signed char> status_;
  /// W's diagonal without compliance, once κ was first added to this step's assembled W.
  Eigen::VectorXd w_diagonal_;
  bool w_has_compliance_ = false;
  const std::vector<double>* caps_ = nullptr;
  long capped_ = -1;
  double capped_law_shift_ = 0;
};

}  // namespace moreau::kernel
