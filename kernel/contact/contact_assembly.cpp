#include "contact_assembly.hpp"

#include <algorithm>
#include <Eigen/Dense>
#include <moreau/factor_matrix.hpp>
#include <moreau/node_fields.hpp>
#include <tuple>

namespace moreau::kernel {

void ContactAssembly::build(const State& st, const std::vector<ContactModel>& models, const ContactSides& cs, bool with_W,
                            LocalProblem& problem) {
  dim_ = st.dimension();
  models_ = &models;
  contacts_ = &cs;
  const int d = dim_;
  const std::size_t nc = cs.size(), nb = st.bodies();
  // H, side by side, from each body's modelization.
  offset_.resize(2 * nc + 1);
  offset_[0] = 0;
  for (std::size_t s = 0; s < 2 * nc; ++s) offset_[s + 1] = offset_[s] + static_cast<std::size_t>(d * models[cs.model[s]].k);
  H_.assign(offset_[2 * nc], 0.0);
  const double one = 1.0;
  for (std::size_t a = 0; a < nc; ++a)
    for (int side = 0; side < 2; ++side) {
      const std::size_t s = 2 * a + side;
      PointOnBody p;
      p.body = static_cast<std::size_t>(cs.body[s]);
      p.nodes = &cs.node[s];
      p.weights = &one;
      p.count = 1;
      for (int k = 0; k < 3; ++k) p.point[k] = cs.point[3 * a + k];
      p.frame = &cs.frame[a * d * d];
      double* H = &H_[offset_[s]];
      models[cs.model[s]].model->contact_jacobian(st, p, H);
      if (side == 1)
        for (std::size_t i = offset_[s]; i < offset_[s + 1]; ++i) H_[i] = -H_[i];
    }
  // The inverses of the touched bodies, compact where their integrator can.
  compact_.assign(nb, -1);
  compact_ok_.assign(nb, 0);
  inverse_.clear();
  int k_all = -1;
  bool uniform = true;
  for (std::size_t s = 0; s < 2 * nc; ++s) {
    const int b = cs.body[s];
    if (compact_[b] >= 0) continue;
    const ContactModel& m = models[cs.model[s]];
    compact_[b] = static_cast<long>(inverse_.size());
    inverse_.resize(inverse_.size() + static_cast<std::size_t>(m.k * m.k));
    compact_ok_[b] = m.integrator->compact_inverse(st, static_cast<std::size_t>(b), &inverse_[compact_[b]]);
    uniform = uniform && compact_ok_[b] && (k_all < 0 || k_all == m.k);
    k_all = m.k;
  }
  problem.dim = d;
  factored_ = uniform && nc > 0;
  if (!factored_) {
    problem.factor = BodyFactor{};
    general_w(st, problem);
    return;
  }
  // The factored form: per contact side its body (−1 when impulses do not move it) and
  // per body its k × k inverse.
  const int k = k_all;
  BodyFactor& f = problem.factor;
  f.k = k;
  f.diagonal.clear();  // the laws' compliance, added after (law_step.hpp)
  f.inverse_mass.assign(nb * k * k, 0.0);
  std::vector<char> moves(nb, 0);
  for (std::size_t b = 0; b < nb; ++b) {
    if (compact_[b] < 0) continue;
    const double* Mi = &inverse_[compact_[b]];
    std::copy(Mi, Mi + k * k, &f.inverse_mass[b * k * k]);
    moves[b] = !std::all_of(Mi, Mi + k * k, [](double x) { return x == 0.0; });
  }
  f.body.resize(2 * nc);
  for (std::size_t s = 0; s < 2 * nc; ++s) f.body[s] = moves[cs.body[s]] ? cs.body[s] : -1;
  if (with_W) {
    f.H.swap(H_);
    problem.W = assemble_w(d, f);
    H_.swap(f.H);
  } else {
    problem.W.resize(0, 0);
  }
}

void ContactAssembly::general_w(const State& st, LocalProblem& problem) const {
  // W = Σ_b H_b LHS_b⁻¹ H_bᵀ over the moving bodies: d × d blocks (α, β) for every pair of
  // contact sides on one body, collected and summed into compressed rows.
  const ContactSides& cs = *contacts_;
  const std::vector<ContactModel>& models = *models_;
  const int d = dim_;
  const std::size_t nc = cs.size(), nb = st.bodies();
  std::vector<std::vector<std::size_t>> sides_of(nb);
  for (std::size_t s = 0; s < 2 * nc; ++s) sides_of[cs.body[s]].push_back(s);
  struct Block {
    std::size_t a, b;
    double v[9];
  };
  std::vector<Block> blocks;
  for (std::size_t b = 0; b < nb; ++b) {
    const auto& sides = sides_of[b];
    if (sides.empty()) continue;
    const ContactModel& m = models[cs.model[sides[0]]];
    const int k = m.k;
    const std::size_t ns = sides.size();
    if (compact_ok_[b]) {
      const double* Mi = &inverse_[compact_[b]];
      if (std::all_of(Mi, Mi + k * k, [](double x) { return x == 0.0; })) continue;  // fixed
      std::vector<double> G(static_cast<std::size_t>(d * k));  // H_i M⁻¹
      for (std::size_t i = 0; i < ns; ++i) {
        const double* Hi = &H_[offset_[sides[i]]];
        for (int r = 0; r < d; ++r)
          for (int c = 0; c < k; ++c) {
            double s = 0;
            for (int l = 0; l < k; ++l) s += Hi[r * k + l] * Mi[l * k + c];
            G[r * k + c] = s;
          }
        for (std::size_t j = 0; j < ns; ++j) {
          const double* Hj = &H_[offset_[sides[j]]];
          Block blk{sides[i] / 2, sides[j] / 2, {}};
          for (int r = 0; r < d; ++r)
            for (int c = 0; c < d; ++c) {
              double s = 0;
              for (int l = 0; l < k; ++l) s += G[r * k + l] * Hj[c * k + l];
              blk.v[r * d + c] = s;
            }
          blocks.push_back(blk);
        }
      }
      continue;
    }
    // A body whose LHS couples its nodes: G = LHS⁻¹ H_bᵀ by its integrator (one column
    // per contact row on the body), then W_b = H_b G, dense among its contact rows.
    const BodyRows rows = st.body(b);
    const std::size_t n = rows.nodes * static_cast<std::size_t>(k), cols = ns * d;
    Eigen::MatrixXd Ht = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(cols));
    for (std::size_t i = 0; i < ns; ++i) {
      const double* Hi = &H_[offset_[sides[i]]];
      const std::size_t local = (cs.node[sides[i]] - rows.first_node) * k;
      for (int r = 0; r < d; ++r)
        for (int l = 0; l < k; ++l) Ht(static_cast<Eigen::Index>(local + l), static_cast<Eigen::Index>(i * d + r)) = Hi[r * k + l];
    }
    Eigen::MatrixXd G(Ht.rows(), Ht.cols());
    m.integrator->apply_inverse(st, b, static_cast<int>(cols), Ht.data(), G.data());
    const Eigen::MatrixXd Wb = Ht.transpose() * G;
    for (std::size_t i = 0; i < ns; ++i)
      for (std::size_t j = 0; j < ns; ++j) {
        Block blk{sides[i] / 2, sides[j] / 2, {}};
        for (int r = 0; r < d; ++r)
          for (int c = 0; c < d; ++c)
            blk.v[r * d + c] = Wb(static_cast<Eigen::Index>(i * d + r), static_cast<Eigen::Index>(j * d + c));
        blocks.push_back(blk);
      }
  }
  std::sort(blocks.begin(), blocks.end(), [](const Block& x, const Block& y) { return std::tie(x.a, x.b) < std::tie(y.a, y.b); });
  // Merge blocks of the same (α, β) (two contacts sharing both bodies), then write the rows.
  std::vector<Block> merged;
  for (const auto& blk : blocks) {
    if (!merged.empty() && merged.back().a == blk.a && merged.back().b == blk.b) {
      for (int i = 0; i < d * d; ++i) merged.back().v[i] += blk.v[i];
    } else {
      merged.push_back(blk);
    }
  }
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(merged.size() * d * d);
  for (const auto& blk : merged)
    for (int r = 0; r < d; ++r)
      for (int c = 0; c < d; ++c)
        t.emplace_back(static_cast<int>(blk.a * d + r), static_cast<int>(blk.b * d + c), blk.v[r * d + c]);
  problem.W.resize(static_cast<Eigen::Index>(nc * d), static_cast<Eigen::Index>(nc * d));
  problem.W.setFromTriplets(t.begin(), t.end());
}

Eigen::VectorXd ContactAssembly::local_velocity(const State& st, Velocity which) const {
  const ContactSides& cs = *contacts_;
  const int d = dim_;
  const std::size_t nc = cs.size();
  Eigen::VectorXd u = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(nc * d));
  double v[64];
  for (std::size_t a = 0; a < nc; ++a)
    for (int side = 0; side < 2; ++side) {
      const std::size_t s = 2 * a + side;
      const ContactModel& m = (*models_)[cs.model[s]];
      const int k = m.k;
      m.model->generalised_velocity(st, which, cs.node[s], v);
      const double* H = &H_[offset_[s]];
      for (int i = 0; i < d; ++i) {
        double sum = 0;
        for (int l = 0; l < k; ++l) sum += H[i * k + l] * v[l];
        u[static_cast<Eigen::Index>(a * d + i)] += sum;
      }
    }
  return u;
}

void ContactAssembly::lend(LocalProblem& p) {
  if (factored_) p.factor.H.swap(H_);
}

void ContactAssembly::take_back(LocalProblem& p) {
  if (!factored_) return;
  H_.swap(p.factor.H);
  p.factor.H.clear();
}

void ContactAssembly::store_reactions(State& st, const Eigen::VectorXd& r) const {
  const ContactSides& cs = *contacts_;
  const int d = dim_;
  std::vector<double*> reaction(models_->size(), nullptr);
  for (std::size_t m = 0; m < models_->size(); ++m) {
    Field* f = st.set((*models_)[m].nodes).find(node_fields::reaction);
    if (!f) continue;
    std::fill(f->data(), f->data() + f->rows() * f->components(), 0.0);
    reaction[m] = f->data();
  }
  for (std::size_t a = 0; a < cs.size(); ++a)
    for (int side = 0; side < 2; ++side) {
      const std::size_t s = 2 * a + side;
      const int k = (*models_)[cs.model[s]].k;
      const double* H = &H_[offset_[s]];
      double* P = reaction[cs.model[s]] + cs.node[s] * k;
      for (int l = 0; l < k; ++l) {
        double sum = 0;
        for (int i = 0; i < d; ++i) sum += H[i * k + l] * r[static_cast<Eigen::Index>(a * d + i)];
        P[l] += sum;
      }
    }
}

}  // namespace moreau::kernel
