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
  // H, side by side, from each body's modelization: a d × k block per support node.
  offset_.resize(2 * nc + 1);
  offset_[0] = 0;
  for (std::size_t s = 0; s < 2 * nc; ++s)
    offset_[s + 1] = offset_[s] + static_cast<std::size_t>(cs.support_count(s) * d * models[cs.model[s]].k);
  H_.assign(offset_[2 * nc], 0.0);
  std::size_t nodes[4];
  double weights[4];
  for (std::size_t a = 0; a < nc; ++a)
    for (int side = 0; side < 2; ++side) {
      const std::size_t s = 2 * a + side;
      PointOnBody p;
      p.body = static_cast<std::size_t>(cs.body[s]);
      p.count = cs.support_count(s);
      for (int j = 0; j < p.count; ++j) {
        nodes[j] = cs.support_node(s, j);
        weights[j] = cs.support_weight(s, j);
      }
      p.nodes = nodes;
      p.weights = weights;
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
    uniform = uniform && compact_ok_[b] && (k_all < 0 || k_all == m.k) && cs.support_count(s) == 1;
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
    // A body whose LHS couples its nodes: its integrator gives G, the blocks of LHS⁻¹
    // among the m nodes its contact points sit on; then W_b = H_b G H_bᵀ, dense among its
    // contact rows (H_b: the sides' blocks placed on those m nodes).
    std::vector<std::size_t> nodes;
    for (const std::size_t s : sides)
      for (int j = 0; j < cs.support_count(s); ++j) nodes.push_back(cs.support_node(s, j));
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
    const Eigen::Index mk = static_cast<Eigen::Index>(nodes.size()) * k, rows = static_cast<Eigen::Index>(ns) * d;
    Eigen::MatrixXd G(mk, mk);
    m.integrator->inverse_blocks(st, b, nodes.data(), static_cast<int>(nodes.size()), G.data());
    Eigen::MatrixXd Hb = Eigen::MatrixXd::Zero(rows, mk);
    for (std::size_t i = 0; i < ns; ++i) {
      const double* Hi = &H_[offset_[sides[i]]];
      for (int j = 0; j < cs.support_count(sides[i]); ++j) {
        const auto col = static_cast<Eigen::Index>(std::lower_bound(nodes.begin(), nodes.end(), cs.support_node(sides[i], j)) -
                                                   nodes.begin()) * k;
        for (int r = 0; r < d; ++r)
          for (int l = 0; l < k; ++l) Hb(static_cast<Eigen::Index>(i) * d + r, col + l) += Hi[(j * d + r) * k + l];
      }
    }
    const Eigen::MatrixXd Wb = Hb * G * Hb.transpose();
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
  // Each node's generalised velocity is asked of its model once per call, not once per
  // contact side on it: a model looks its fields up by name at every call (10⁴ spheres:
  // 6·10⁴ sides on 10⁴ bodies, about 8 ms a step for the two calls of a step). The values,
  // and so u, are the same.
  std::vector<double>& seen = velocity_seen_;
  if (velocity_slot_.size() < models_->size()) velocity_slot_.resize(models_->size());
  seen.clear();
  const std::uint64_t call = ++velocity_call_;
  for (std::size_t a = 0; a < nc; ++a)
    for (int side = 0; side < 2; ++side) {
      const std::size_t s = 2 * a + side;
      const ContactModel& m = (*models_)[cs.model[s]];
      const int k = m.k;
      std::vector<VelocitySlot>& slots = velocity_slot_[static_cast<std::size_t>(cs.model[s])];
      for (int j = 0; j < cs.support_count(s); ++j) {
        const std::size_t n = cs.support_node(s, j);
        if (n >= slots.size()) slots.resize(n + 1);
        VelocitySlot& slot = slots[n];
        if (slot.call != call) {
          slot.call = call;
          slot.at = seen.size();
          seen.resize(seen.size() + static_cast<std::size_t>(k));
          m.model->generalised_velocity(st, which, n, &seen[slot.at]);
        }
        const double* v = &seen[slot.at];
        const double* H = &H_[offset_[s] + static_cast<std::size_t>(j * d * k)];
        for (int i = 0; i < d; ++i) {
          double sum = 0;
          for (int l = 0; l < k; ++l) sum += H[i * k + l] * v[l];
          u[static_cast<Eigen::Index>(a * d + i)] += sum;
        }
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
      for (int j = 0; j < cs.support_count(s); ++j) {
        const double* H = &H_[offset_[s] + static_cast<std::size_t>(j * d * k)];
        double* P = reaction[cs.model[s]] + cs.support_node(s, j) * k;
        for (int l = 0; l < k; ++l) {
          double sum = 0;
          for (int i = 0; i < d; ++i) sum += H[i * k + l] * r[static_cast<Eigen::Index>(a * d + i)];
          P[l] += sum;
        }
      }
    }
}

fclib::GlobalProblem ContactAssembly::global_problem(const State& st, const Eigen::VectorXd& q, const Eigen::VectorXd& mu) const {
  const ContactSides& cs = *contacts_;
  const std::vector<ContactModel>& models = *models_;
  const int d = dim_;
  const std::size_t nc = cs.size();
  // The touched bodies, in body order, and each one's unknowns in the global numbering
  // (−1: constrained, not an unknown of the problem).
  std::vector<int> touched;
  for (std::size_t s = 0; s < 2 * nc; ++s) touched.push_back(cs.body[s]);
  std::sort(touched.begin(), touched.end());
  touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
  std::vector<std::vector<long>> index(st.bodies());
  std::vector<Eigen::Triplet<double>> m_entries;
  std::vector<double> v_free;
  long ndof = 0;
  std::vector<double> vbuf(64);
  for (const int b : touched) {
    const BodyRows rows = st.body(static_cast<std::size_t>(b));
    const ContactModel& m = models[static_cast<std::size_t>(rows.model)];
    const int k = m.k;
    const std::size_t n = rows.nodes * static_cast<std::size_t>(k);
    std::vector<long>& idx = index[static_cast<std::size_t>(b)];
    idx.assign(n, -1);
    std::vector<LhsEntry> entries;
    std::vector<int> constrained;
    if (compact_ok_[static_cast<std::size_t>(b)]) {
      // A compact inverse: invert its block on the components that move.
      const Eigen::Map<const Eigen::MatrixXd> Mi(&inverse_[static_cast<std::size_t>(compact_[static_cast<std::size_t>(b)])], k, k);
      std::vector<int> free;
      for (int i = 0; i < k; ++i)
        if (Mi.row(i).cwiseAbs().maxCoeff() > 0) free.push_back(i);
        else constrained.push_back(i);
      Eigen::MatrixXd sub(free.size(), free.size());
      for (std::size_t i = 0; i < free.size(); ++i)
        for (std::size_t j = 0; j < free.size(); ++j) sub(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = Mi(free[i], free[j]);
      const Eigen::MatrixXd M = sub.inverse();
      for (std::size_t i = 0; i < free.size(); ++i)
        for (std::size_t j = 0; j < free.size(); ++j)
          if (M(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) != 0)
            entries.push_back(LhsEntry{free[i], free[j], M(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j))});
    } else if (!m.integrator->lhs_entries(st, static_cast<std::size_t>(b), entries, constrained)) {
      throw RunError("the contact problem cannot be exported in FCLib's global form: the integrator of body \"" +
                     st.names()[static_cast<std::size_t>(b)] + "\" gives neither a compact inverse nor its LHS");
    }
    std::vector<char> is_constrained(n, 0);
    for (const int c : constrained) is_constrained[static_cast<std::size_t>(c)] = 1;
    for (std::size_t i = 0; i < n; ++i)
      if (!is_constrained[i]) idx[i] = ndof++;
    for (const auto& e : entries)
      m_entries.emplace_back(idx[static_cast<std::size_t>(e.row)], idx[static_cast<std::size_t>(e.column)], e.value);
    for (std::size_t node = 0; node < rows.nodes; ++node) {
      m.model->generalised_velocity(st, Velocity::free, rows.first_node + node, vbuf.data());
      for (int l = 0; l < k; ++l)
        if (idx[node * k + static_cast<std::size_t>(l)] >= 0) v_free.push_back(vbuf[static_cast<std::size_t>(l)]);
    }
  }
  fclib::GlobalProblem g;
  g.dim = d;
  g.M.resize(ndof, ndof);
  g.M.setFromTriplets(m_entries.begin(), m_entries.end());
  const Eigen::Map<const Eigen::VectorXd> vf(v_free.data(), ndof);
  g.f = g.M * vf;
  // FCLib's H is n_dof × d·nc: our H transposed, on the problem's unknowns.
  std::vector<Eigen::Triplet<double>> h_entries;
  for (std::size_t a = 0; a < nc; ++a)
    for (int side = 0; side < 2; ++side) {
      const std::size_t s = 2 * a + side;
      const int b = cs.body[s];
      const int k = models[static_cast<std::size_t>(cs.model[s])].k;
      const std::size_t first = st.body(static_cast<std::size_t>(b)).first_node;
      for (int j = 0; j < cs.support_count(s); ++j) {
        const double* H = &H_[offset_[s] + static_cast<std::size_t>(j * d * k)];
        const std::size_t node = cs.support_node(s, j) - first;
        for (int i = 0; i < d; ++i)
          for (int l = 0; l < k; ++l) {
            const long col = index[static_cast<std::size_t>(b)][node * k + static_cast<std::size_t>(l)];
            if (col >= 0 && H[i * k + l] != 0) h_entries.emplace_back(col, static_cast<long>(a * d) + i, H[i * k + l]);
          }
      }
    }
  g.H.resize(ndof, static_cast<Eigen::Index>(nc * d));
  g.H.setFromTriplets(h_entries.begin(), h_entries.end());
  g.w = q - g.H.transpose() * vf;
  g.mu = mu;
  return g;
}

}  // namespace moreau::kernel
