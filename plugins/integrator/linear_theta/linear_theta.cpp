// `linear_theta`: the θ-scheme of the seed's eq. 6 for linear modelizations (`elastic`),
// body by body, from what the modelization gives (Modelization::linear_bulk):
//   LHS = M + hθC + h²θ²K,
//   RHS = [M − h(1−θ)C − h²θ(1−θ)K] v⁻ − hK u⁻ + h[(1−θ)f⁻ + θf⁺],
//   LHS v⁺ = RHS + Hᵀr,   u⁺ = u⁻ + h[(1−θ)v⁻ + θv⁺],   position = reference + u,
// with f the constant loads, gravity and the step's external forces (force plugins: the
// same at both ends of the step). Fixed unknowns and imposed velocities (drivers on node
// groups) are constrained: the free ones solve LHS_ff v_f = RHS_f − LHS_fc v_c + p_f, with
// LHS_ff factorised once per run (fem::LinearThetaScheme, sparse Cholesky chosen by the
// benchmark, docs/deformable.md) and again only when the set of driven unknowns changes.
//
// For the contact side: LHS_b⁻¹ on columns (apply_inverse), and the blocks of LHS_b⁻¹
// among the nodes the contacts sit on (inverse_blocks), which W needs: z_a · z_b with
// z = D^{-1/2} L⁻¹ P e from the factor (fem::FactorColumn: a partial forward solve up the
// elimination tree, a small part of a full solve; k per node), kept with the pair blocks
// while the nodes stay in contact. Block (a, b) is always z_lower · z_higher, so the
// numbers do not depend on what was kept (restarts stay bit-identical).
#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <moreau/integrator.hpp>
#include <moreau/linear_bulk.hpp>
#include <moreau/node_fields.hpp>

#include "fem/theta_scheme.hpp"

namespace {

using namespace moreau;
namespace N = moreau::node_fields;

class LinearTheta : public Integrator {
  struct Body;

 public:
  static Schema schema() { return {}; }
  static constexpr const char* doc =
      "theta-scheme of linear modelizations (elastic): LHS = M + h theta C + h^2 theta^2 K factorised once (eq. 6)";
  LinearTheta(const Params&, const BuildContext& c) : h_(c.time_step), theta_(c.theta) {}

  void prepare(State& st, const Modelization& model) override {
    nodes_ = model.node_set();
    d_ = st.dimension();
    k_ = model.node_dofs(d_);
    for (const char* f : {N::displacement, N::velocity, N::free_velocity})
      if (!st.has(nodes_, f))
        throw InputError("/models", "linear_theta integrates linear modelizations with node fields displacement, velocity "
                                    "and free_velocity: \"" + nodes_ + "\" has no '" + f + "'");
    with_position_ = st.has(nodes_, N::position) && st.has(nodes_, N::reference_position) && k_ == d_;
    const int model_index = st.find_model(model_name(st));
    bodies_.clear();
    for (std::size_t b = 0; b < st.bodies(); ++b) {
      if (st.body(b).model != model_index) continue;
      auto B = std::make_unique<Body>();
      B->body = b;
      const BodyRows rows = st.body(b);
      B->first = rows.first_node;
      B->nodes = rows.nodes;
      if (!model.linear_bulk(st, b, B->bulk))
        throw InputError("/models", "linear_theta integrates linear modelizations: \"" + st.models()[model_index].name +
                                        "\" gives no linear bulk (Modelization::linear_bulk)");
      const Eigen::Index n = static_cast<Eigen::Index>(B->nodes) * k_;
      if (B->bulk.C.rows() == 0) B->bulk.C.resize(n, n);
      B->constrained = B->bulk.fixed;
      factorise(*B);
      bodies_.push_back(std::move(B));
    }
  }

  void free_velocity(StepContext& c) override {
    State& st = c.state;
    const double* u = st.field(nodes_, N::displacement).data(Depth::begin);
    const double* v = st.field(nodes_, N::velocity).data(Depth::begin);
    const Field* imposed = st.set(nodes_).find(N::imposed_velocity);
    const double* F = c.external_forces && st.has(nodes_, N::force) ? st.field(nodes_, N::force).data() : nullptr;
    double* vf = st.field(nodes_, N::free_velocity).data();
    Eigen::VectorXd g(d_);
    for (int i = 0; i < d_; ++i) g[i] = c.gravity[static_cast<std::size_t>(i)];
    for (auto& Bp : bodies_) {
      Body& B = *Bp;
      const Eigen::Index n = static_cast<Eigen::Index>(B.nodes) * k_, off = static_cast<Eigen::Index>(B.first) * k_;
      // The constrained unknowns of this step: fixed, and the driven ones (non-NaN).
      std::vector<int> constrained = B.bulk.fixed;
      if (imposed)
        for (Eigen::Index i = 0; i < n; ++i)
          if (!std::isnan(imposed->data()[off + i])) constrained.push_back(static_cast<int>(i));
      std::sort(constrained.begin(), constrained.end());
      constrained.erase(std::unique(constrained.begin(), constrained.end()), constrained.end());
      if (constrained != B.constrained) {
        B.constrained = std::move(constrained);
        factorise(B);
      }
      Eigen::VectorXd f = Eigen::VectorXd::Zero(n);
      if (B.bulk.load.size() == n) f += B.bulk.load;
      if (B.bulk.gravity.rows() == n) f += B.bulk.gravity * g;
      if (F) f += Eigen::Map<const Eigen::VectorXd>(F + off, n);
      Eigen::VectorXd vc(static_cast<Eigen::Index>(B.constrained.size()));
      for (std::size_t i = 0; i < B.constrained.size(); ++i) {
        const double x = imposed ? imposed->data()[off + B.constrained[i]] : NAN;
        vc[static_cast<Eigen::Index>(i)] = std::isnan(x) ? 0.0 : x;  // fixed: 0
      }
      const Eigen::VectorXd out = B.scheme->free_velocity(Eigen::Map<const Eigen::VectorXd>(u + off, n),
                                                          Eigen::Map<const Eigen::VectorXd>(v + off, n), f, f, vc);
      Eigen::Map<Eigen::VectorXd>(vf + off, n) = out;
    }
  }

  void update_dofs(StepContext& c) override {
    State& st = c.state;
    const double a = c.h * (1 - c.theta), b = c.h * c.theta;
    const double* u0 = st.field(nodes_, N::displacement).data(Depth::begin);
    double* u1 = st.field(nodes_, N::displacement).data(Depth::end);
    const double* v0 = st.field(nodes_, N::velocity).data(Depth::begin);
    double* v1 = st.field(nodes_, N::velocity).data(Depth::end);
    const double* vf = st.field(nodes_, N::free_velocity).data();
    const double* P = c.contact_impulses && st.has(nodes_, N::reaction) ? st.field(nodes_, N::reaction).data() : nullptr;
    for (auto& Bp : bodies_) {
      const Body& B = *Bp;
      const Eigen::Index n = static_cast<Eigen::Index>(B.nodes) * k_, off = static_cast<Eigen::Index>(B.first) * k_;
      Eigen::Map<Eigen::VectorXd> v(v1 + off, n);
      v = Eigen::Map<const Eigen::VectorXd>(vf + off, n);
      if (P) {
        const Eigen::Map<const Eigen::VectorXd> p(P + off, n);
        if (p.cwiseAbs().maxCoeff() > 0) v += B.scheme->impulse_response(p);
      }
      for (Eigen::Index i = 0; i < n; ++i) u1[off + i] = u0[off + i] + a * v0[off + i] + b * v[i];
    }
    if (!with_position_) return;
    const double* X = st.field(nodes_, N::reference_position).data();
    double* x1 = st.field(nodes_, N::position).data(Depth::end);
    const std::size_t total = st.set(nodes_).rows() * static_cast<std::size_t>(d_);
    for (std::size_t i = 0; i < total; ++i) x1[i] = X[i] + u1[i];
  }

  void detection_configuration(StepContext& c) override {
    // Detection on q⁻ + (1−θ)h v⁻, as for rigid bodies; a node may travel 2h|v⁻| + h²|g|.
    State& st = c.state;
    if (!with_position_ || !st.has(nodes_, N::detection_position)) return;
    const double a = (1 - c.theta) * c.h;
    const double* x = st.field(nodes_, N::position).data(Depth::begin);
    const double* v = st.field(nodes_, N::velocity).data(Depth::begin);
    double* p = st.field(nodes_, N::detection_position).data();
    double* travel = st.has(nodes_, N::travel) ? st.field(nodes_, N::travel).data() : nullptr;
    double g = 0;
    for (double gk : c.gravity) g += gk * gk;
    g = std::sqrt(g);
    const std::size_t rows = st.set(nodes_).rows();
    for (std::size_t i = 0; i < rows; ++i) {
      double v2 = 0;
      for (int k = 0; k < d_; ++k) {
        p[i * d_ + k] = x[i * d_ + k] + a * v[i * d_ + k];
        v2 += v[i * d_ + k] * v[i * d_ + k];
      }
      if (travel) {
        travel[2 * i] = 2 * c.h * std::sqrt(v2) + c.h * c.h * g;
        travel[2 * i + 1] = 0;
      }
    }
  }

  bool compact_inverse(const State&, std::size_t, double*) const override { return false; }

  void apply_inverse(const State&, std::size_t body, int columns, const double* in, double* out) const override {
    const Body& B = body_of(body);
    const Eigen::Index n = static_cast<Eigen::Index>(B.nodes) * k_;
    Eigen::Map<Eigen::MatrixXd>(out, n, columns) =
        B.scheme->impulse_responses(Eigen::Map<const Eigen::MatrixXd>(in, n, columns));
  }

  void inverse_blocks(const State&, std::size_t body, const std::size_t* nodes, int count, double* out) const override {
    Body& B = body_of(body);
    std::vector<std::size_t> local(static_cast<std::size_t>(count));
    for (int i = 0; i < count; ++i) local[i] = nodes[i] - B.first;
    // Every factor linear_theta makes (the automatic backend: CHOLMOD's, or Eigen's LDLᵀ)
    // shows its columns.
    factor_column_blocks(B, local, out);
  }

  /// inverse_blocks from the factor's columns (fem::FactorColumn): per node its k columns
  /// z = D^{-1/2} L⁻¹ P e (a partial forward solve each, up the elimination tree only), kept
  /// while the node is in contact, and per pair of nodes its k × k block z_a · z_b, kept
  /// too. Blocks are always z_lower · z_higher, so they do not depend on what was kept.
  void factor_column_blocks(Body& B, const std::vector<std::size_t>& local, double* out) const {
    const std::size_t k = static_cast<std::size_t>(k_), m = local.size() * k;
    // Past the memory budget, only the asked nodes' columns and blocks stay.
    std::size_t missing = 0;
    for (const std::size_t a : local) missing += B.z.count(a) == 0;
    if (B.z_entries + missing * B.z_estimate > budget_bytes / sizeof(double) / 2 ||
        B.pairs.size() > budget_bytes / sizeof(double) / 2 / (k * k)) {
      std::map<std::size_t, std::vector<fem::FactorColumn>> asked;
      B.z_entries = 0;
      for (const std::size_t a : local)
        if (auto it = B.z.find(a); it != B.z.end()) {
          for (const auto& c : it->second) B.z_entries += c.index.size();
          asked.emplace(a, std::move(it->second));
        }
      B.z = std::move(asked);
      B.pairs.clear();
    }
    const auto& partition = B.scheme->partition();
    for (const std::size_t a : local) {
      if (B.z.count(a)) continue;
      std::vector<fem::FactorColumn>& cols = B.z[a];
      cols.resize(k);
      for (std::size_t c = 0; c < k; ++c) {
        const int eq = partition.equation(static_cast<int>(a * k + c));
        if (eq >= 0) cols[c] = B.scheme->factor().factor_column(eq);  // constrained: none (infinite mass)
        B.z_entries += cols[c].index.size();
        B.z_estimate = std::max(B.z_estimate, cols[c].index.size());
      }
    }
    // G(i·k + α, j·k + c) = [LHS⁻¹](a_i α, a_j c).
    for (std::size_t j = 0; j < local.size(); ++j)
      for (std::size_t i = 0; i < local.size(); ++i) {
        const bool lower_i = local[i] <= local[j];
        const std::size_t lo = lower_i ? local[i] : local[j], hi = lower_i ? local[j] : local[i];
        auto [it, fresh] = B.pairs.try_emplace({lo, hi});
        std::vector<double>& blk = it->second;  // blk[α k + β] = z_lo,α · z_hi,β
        if (fresh) {
          blk.resize(k * k);
          const auto &zl = B.z.at(lo), &zh = B.z.at(hi);
          for (std::size_t al = 0; al < k; ++al)
            for (std::size_t be = 0; be < k; ++be) blk[al * k + be] = fem::dot(zl[al], zh[be]);
        }
        for (std::size_t c = 0; c < k; ++c)
          for (std::size_t al = 0; al < k; ++al)
            out[(j * k + c) * m + i * k + al] = lower_i ? blk[al * k + c] : blk[c * k + al];
      }
  }

  bool lhs_entries(const State&, std::size_t body, std::vector<LhsEntry>& entries, std::vector<int>& constrained) const override {
    const Body& B = body_of(body);
    const auto& free = B.scheme->partition().free();
    const fem::SparseMatrix lhs = B.scheme->partition().free_block(
        fem::theta_lhs(B.bulk.M, B.bulk.C, B.bulk.K, B.scheme->step(), B.scheme->theta()));
    entries.clear();
    for (int col = 0; col < lhs.outerSize(); ++col)
      for (fem::SparseMatrix::InnerIterator it(lhs, col); it; ++it)
        entries.push_back(LhsEntry{free[static_cast<std::size_t>(it.row())], free[static_cast<std::size_t>(col)], it.value()});
    constrained = B.scheme->partition().constrained();
    return true;
  }

 private:
  static constexpr std::size_t budget_bytes = std::size_t{256} << 20;  ///< kept factor columns and blocks, per body

  struct Body {
    std::size_t body = 0, first = 0, nodes = 0;
    LinearBulk bulk;
    std::vector<int> constrained;  ///< unknowns within the body, sorted
    std::unique_ptr<fem::LinearThetaScheme> scheme;
    // For W (factor_column_blocks): per node its k factor columns z, per node pair the
    // block z_a · z_b.
    std::map<std::size_t, std::vector<fem::FactorColumn>> z;
    std::map<std::pair<std::size_t, std::size_t>, std::vector<double>> pairs;
    std::size_t z_entries = 0, z_estimate = 0;
  };

  /// The model's name, from its node set ("<model>.nodes").
  std::string model_name(const State& st) const {
    for (const auto& m : st.models())
      if (m.nodes == nodes_) return m.name;
    return {};
  }

  void factorise(Body& B) const {
    const int dofs = static_cast<int>(B.nodes) * k_;
    try {
      B.scheme = std::make_unique<fem::LinearThetaScheme>(B.bulk.M, B.bulk.C, B.bulk.K, h_, theta_,
                                                          fem::DofPartition(dofs, B.constrained));
    } catch (const std::exception& e) {
      throw RunError("linear_theta: body " + std::to_string(B.body) + ": cannot factorise M + h theta C + h^2 theta^2 K: " +
                     e.what());
    }
    B.z.clear();
    B.pairs.clear();
    B.z_entries = 0;
  }

  Body& body_of(std::size_t body) const {
    for (const auto& B : bodies_)
      if (B->body == body) return *B;
    throw std::logic_error("linear_theta: body " + std::to_string(body) + " is not one of its bodies");
  }

  double h_, theta_;
  int d_ = 3, k_ = 3;
  bool with_position_ = false;
  std::string nodes_;
  std::vector<std::unique_ptr<Body>> bodies_;
};

MOREAU_REGISTER(LinearTheta, "linear_theta")

}  // namespace

MOREAU_PLUGIN_LIBRARY("moreau_integrator_linear_theta")
