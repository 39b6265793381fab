#include "law_step.hpp"

#include <algorithm>
#include <cmath>
#include <moreau/contact_error.hpp>
#include <moreau/contact_fields.hpp>
#include <moreau/error.hpp>
#include <moreau/factor_matrix.hpp>
#include <moreau/law_fields.hpp>
#include <stdexcept>

namespace moreau::kernel {

namespace C = moreau::contact_fields;
namespace LF = moreau::law_fields;

void LawStep::setup(State& st, const std::vector<Owned<Law>>& laws, const std::vector<std::string>& names,
                    const std::vector<std::string>& pointers) {
  laws_ = &laws;
  const int dim = st.dimension();
  needs_.clear();
  fields_.assign(laws.size(), {});
  EntitySet& contacts = st.set(sets::contacts);
  for (std::size_t l = 0; l < laws.size(); ++l) {
    needs_.push_back(laws[l]->needs());
    update_ = update_ || needs_.back().update;
    iterate_ = iterate_ || (needs_.back().update && needs_.back().iterate);
    for (FieldSpec f : laws[l]->fields(dim)) {
      // Internal variables follow the contact (persist), hold start- and end-of-step
      // values, are written every frame and restored on restart: the same for every law.
      f.set = sets::contacts;
      f.depths = 2;
      f.persist = true;
      f.restart = true;
      f.output = FieldOutput::frame;
      f.needed = Needed::contacts;
      const int comps = f.components(dim);
      if (comps <= 0) continue;
      if (const Field* old = contacts.find(f.name)) {
        const bool shared = old->spec().depths == 2 && old->spec().persist && old->components() == comps;
        if (!shared)
          throw InputError(pointers[l], "law \"" + names[l] + "\" keeps a per-contact variable named \"" + f.name +
                                            "\", which the contacts set already has with another meaning or shape; "
                                            "expected a law whose variables do not clash (docs/laws.md)");
      }
      contacts.declare(f);
      fields_[l].names.push_back(f.name);
      variables_ = true;
      fields_[l].components.push_back(comps);
      counts_ = counts_ || f.name == LF::bond;
    }
  }
  if (counts_) {
    auto count = [](const char* name, bool restart, const char* doc) {
      return field_spec(LF::set, name, 1, 1, 1, "1", FieldOutput::frame, restart, doc, FileType::int32, Needed::contacts);
    };
    EntitySet& set = st.add_set(LF::set);
    set.declare(count(LF::bonds, false, "intact bonds of the law at the end of the step"));
    set.declare(count(LF::broken_count, true, "bonds of the law broken since the run began"));
    if (set.rows() == 0) set.add_rows(laws.size());
  }
}

void LawStep::begin(State& st, long step, double h, double theta, const std::vector<int>& law,
                    const std::vector<double>& gap, const Eigen::VectorXd& u_begin, const Eigen::VectorXd& q_free,
                    const std::vector<char>& new_contact) {
  d_ = st.dimension();
  const int d = d_;
  nc_ = law.size();
  law_ = &law;
  q_free_ = &q_free;
  u_begin_ = &u_begin;
  EntitySet& contacts = st.set(sets::contacts);
  const double* status = contacts.field(C::status).data();
  in_.resize(nc_);
  for (std::size_t a = 0; a < nc_; ++a) {
    LawInput& in = in_[a];
    in.gap = gap[a];
    in.normal_velocity_begin = u_begin[static_cast<Eigen::Index>(a * d)];
    in.h = h;
    in.theta = theta;
    in.normal_velocity_free = q_free[static_cast<Eigen::Index>(a * d)];
    in.dim = d;
    in.velocity_begin = u_begin.data() + a * d;
    in.status_begin = static_cast<int>(status[a]);
    in.new_contact = new_contact[a] != 0;
    in.step = step;
  }
  for (auto& lf : fields_) {
    lf.begin.clear();
    lf.end.clear();
    for (const auto& name : lf.names) {
      Field& f = contacts.field(name);
      lf.begin.push_back(f.data(Depth::begin));
      lf.end.push_back(f.data(Depth::end));
    }
  }
  w_has_compliance_ = false;
  status_.assign(nc_, 0);
}

LawVariables LawStep::variables(std::size_t a) const {
  const LawFields& lf = fields_[static_cast<std::size_t>((*law_)[a])];
  return LawVariables(lf.begin.data(), lf.end.data(), lf.components.data(), a);
}

void LawStep::to_solver(LocalProblem& P, Eigen::VectorXd& r) {
  const int d = d_;
  const auto n = static_cast<Eigen::Index>(nc_ * d);
  shift_.setZero(n);
  cohesion_.setZero(n);
  compliance_.setZero(n);
  any_cohesion_ = any_compliance_ = false;
  P.mu.resize(static_cast<Eigen::Index>(nc_));
  LawTerms t;
  for (std::size_t a = 0; a < nc_; ++a) {
    const Law& law = *(*laws_)[static_cast<std::size_t>((*law_)[a])];
    t = LawTerms{};
    law.terms(in_[a], variables(a), t);
    P.mu[static_cast<Eigen::Index>(a)] = t.friction;
    const auto i = static_cast<Eigen::Index>(a * d);
    for (int k = 0; k < d; ++k) {
      shift_[i + k] = t.shift[k];
      compliance_[i + k] = t.compliance[k];
      any_compliance_ = any_compliance_ || t.compliance[k] != 0;
    }
    cohesion_[i] = t.cohesion;
    any_cohesion_ = any_cohesion_ || t.cohesion != 0;
    if (caps_ && (*caps_)[a] < shift_[i]) {
      if (capped_ < 0 || shift_[i] - (*caps_)[a] > capped_law_shift_ - (*caps_)[static_cast<std::size_t>(capped_)]) {
        capped_ = static_cast<long>(a);
        capped_law_shift_ = shift_[i];
      }
      shift_[i] = (*caps_)[a];
    }
  }
  set_compliance(P);
  // q' = q_free + s − W' c e_n; r' = r + c e_n.
  P.q = *q_free_ + shift_;
  if (any_cohesion_) {
    if (P.W.rows() == n)
      scratch_ = P.W * cohesion_;
    else
      multiply_w(d, P.factor, cohesion_, scratch_, product_impulse_, product_dv_);
    P.q -= scratch_;
  }
  if (r.size() != n) r = Eigen::VectorXd::Zero(n);
  r += cohesion_;
}

void LawStep::set_compliance(LocalProblem& P) {
  const auto n = static_cast<Eigen::Index>(nc_ * d_);
  if (P.factor.present()) {
    if (any_compliance_)
      P.factor.diagonal.assign(compliance_.data(), compliance_.data() + n);
    else
      P.factor.diagonal.clear();
  }
  if (P.W.rows() != n || (!any_compliance_ && !w_has_compliance_)) return;
  if (!w_has_compliance_) {
    // The first compliance of this step's W: an entry on every diagonal position (W's own
    // pattern may lack one where neither body moves), W's values kept to add κ to.
    w_diagonal_ = P.W.diagonal();
    Eigen::SparseMatrix<double, Eigen::RowMajor> D(n, n);
    D.reserve(Eigen::VectorXi::Constant(n, 1));
    for (Eigen::Index i = 0; i < n; ++i) D.insert(i, i) = 0.0;
    D.makeCompressed();
    P.W = P.W + D;
    w_has_compliance_ = true;
  }
  for (Eigen::Index i = 0; i < n; ++i) P.W.coeffRef(i, i) = w_diagonal_[i] + compliance_[i];
}

void LawStep::from_solver(const LocalProblem& P, Eigen::VectorXd& r, Eigen::VectorXd& u, double error) {
  const int d = d_;
  // A solve to error e leaves natural-map residuals up to e times the denominator: a
  // sticking contact may show a slip velocity that large. Counting it as sliding would
  // break bonds (and switch to dynamic friction) by the solver's tolerance, not the
  // mechanics: a wall solved to 1e-3 would crumble where one solved to 1e-8 stands.
  const double slip = std::max(1e-9, std::isfinite(error) ? error * error_denominator(P) : 0.0);
  r_solver_ = r;
  u_solver_ = u;
  r -= cohesion_;
  u -= shift_ + compliance_.cwiseProduct(r);
  for (std::size_t a = 0; a < nc_; ++a) {
    const double* ra = r_solver_.data() + a * d;
    const double* ua = u_solver_.data() + a * d;
    double rt = 0, ut = 0;
    for (int k = 1; k < d; ++k) {
      rt += ra[k] * ra[k];
      ut += ua[k] * ua[k];
    }
    const double mu = P.mu[static_cast<Eigen::Index>(a)];
    status_[a] = ra[0] > 0 ? ((std::sqrt(ut) > slip && std::sqrt(rt) >= mu * ra[0] * (1 - 1e-6)) ? 2 : 1) : 0;
  }
}

bool LawStep::update(const Eigen::VectorXd& r, const Eigen::VectorXd& u) {
  if (!update_) return false;
  const int d = d_;
  bool consistent = true;
  for (std::size_t a = 0; a < nc_; ++a) {
    const auto l = static_cast<std::size_t>((*law_)[a]);
    if (!needs_[l].update) continue;
    LawResult res{r.data() + a * d, u.data() + a * d, status_[a]};
    const bool ok = (*laws_)[l]->update(in_[a], res, variables(a));
    if (needs_[l].iterate) consistent = consistent && ok;
  }
  return !consistent;
}

void LawStep::finish(State& st) {
  if (!counts_) return;
  EntitySet& set = st.set(LF::set);
  double* bonds = set.field(LF::bonds).data();
  double* broken = set.field(LF::broken_count).data();
  std::fill(bonds, bonds + set.rows(), 0.0);
  const Field& bond = st.field(sets::contacts, LF::bond);
  const double* before = bond.data(Depth::begin);
  const double* after = bond.data(Depth::end);
  for (std::size_t a = 0; a < nc_; ++a) {
    const auto l = static_cast<std::size_t>((*law_)[a]);
    if (after[a] == LF::intact) bonds[l] += 1;
    if (after[a] == LF::broken && before[a] != LF::broken) broken[l] += 1;
  }
}

void LawStep::no_contacts(State& st) {
  if (!counts_) return;
  Field& bonds = st.field(LF::set, LF::bonds);
  std::fill(bonds.data(), bonds.data() + bonds.rows(), 0.0);
}

}  // namespace moreau::kernel
