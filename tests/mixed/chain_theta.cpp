// Integrator `chain_theta` (test only): the θ-scheme of the seed's eq. 6 for the `chain`
// modelization, body by body, with K the linearised spring stiffness (constant):
//   LHS = M + h²θ²K,   LHS (v_free − v⁻) = h (−K u⁻ + M g + F) − θ h² K v⁻,
//   v⁺ = v_free + LHS⁻¹ (Hᵀ r),   x⁺ = x⁻ + h [(1−θ) v⁻ + θ v⁺],   u = x − X (rest).
// LHS couples a body's nodes: it is factorised once per body (dense Cholesky: test bodies
// are small), and apply_inverse solves with it; compact_inverse says no, so the kernel
// assembles W from the factorisation.
#include <Eigen/Dense>
#include <cmath>
#include <moreau/integrator.hpp>

#include "chain_fields.hpp"

namespace {

using namespace moreau;
namespace C = moreau_test::chain;
namespace N = moreau::node_fields;

class ChainTheta : public Integrator {
 public:
  static Schema schema() { return {}; }
  static constexpr const char* doc = "test: theta-scheme for chains of springs (LHS = M + h^2 theta^2 K)";
  ChainTheta(const Params&, const BuildContext& c) : h_(c.time_step) {}

  void prepare(State& st, const Modelization& model) override {
    if (model.node_set() != C::nodes) throw InputError("/models", "chain_theta integrates chain bodies only");
    d_ = st.dimension();
    theta_ = -1;  // factorised at the first step, when θ is known
    model_ = st.find_model(C::model);
    bodies_.clear();
    for (std::size_t b = 0; b < st.bodies(); ++b)
      if (st.body(b).model == model_) bodies_.push_back(b);
  }

  void free_velocity(StepContext& c) override {
    State& st = c.state;
    factorise(st, c.theta);
    const int d = d_;
    const double h = c.h, th = c.theta;
    const double* x = st.field(C::nodes, N::position).data(Depth::begin);
    const double* X = st.field(C::nodes, C::rest_position).data();
    const double* v = st.field(C::nodes, C::velocity).data(Depth::begin);
    const double* m = st.field(C::nodes, C::mass).data();
    const double* F = c.external_forces ? st.field(C::nodes, N::force).data() : nullptr;
    double* vf = st.field(C::nodes, C::free_velocity).data();
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
      const Body& B = body_[i];
      const long n = static_cast<long>(B.nodes) * d;
      Eigen::VectorXd u(n), v0(n), rhs(n);
      for (long j = 0; j < n; ++j) {
        u[j] = x[B.first * d + j] - X[B.first * d + j];
        v0[j] = v[B.first * d + j];
      }
      rhs = -h * (B.K * u) - th * h * h * (B.K * v0);
      for (long j = 0; j < n; ++j) {
        const std::size_t node = B.first + static_cast<std::size_t>(j / d);
        rhs[j] += h * m[node] * c.gravity[j % d] + (F ? h * F[B.first * d + j] : 0.0);
      }
      const Eigen::VectorXd dv = B.lhs.solve(rhs);
      for (long j = 0; j < n; ++j) vf[B.first * d + j] = v0[j] + dv[j];
    }
  }

  void update_dofs(StepContext& c) override {
    State& st = c.state;
    const int d = d_;
    const double a = c.h * (1 - c.theta), b = c.h * c.theta;
    const double* x0 = st.field(C::nodes, N::position).data(Depth::begin);
    double* x1 = st.field(C::nodes, N::position).data(Depth::end);
    const double* v0 = st.field(C::nodes, C::velocity).data(Depth::begin);
    double* v1 = st.field(C::nodes, C::velocity).data(Depth::end);
    const double* vf = st.field(C::nodes, C::free_velocity).data();
    const double* P = c.contact_impulses ? st.field(C::nodes, N::reaction).data() : nullptr;
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
      const Body& B = body_[i];
      const long n = static_cast<long>(B.nodes) * d;
      Eigen::VectorXd dv = Eigen::VectorXd::Zero(n);
      if (P) dv = B.lhs.solve(Eigen::Map<const Eigen::VectorXd>(P + B.first * d, n));
      for (long j = 0; j < n; ++j) {
        const std::size_t k = B.first * d + static_cast<std::size_t>(j);
        v1[k] = vf[k] + dv[j];
        x1[k] = x0[k] + a * v0[k] + b * v1[k];
      }
    }
    // Spring tensions at the end of the step (linearised): k e·(u_b − u_a).
    const double* X = st.field(C::nodes, C::rest_position).data();
    const Field& ends = st.field(C::springs, C::ends);
    const double* k = st.field(C::springs, C::stiffness).data();
    double* t = st.field(C::springs, C::tension).data();
    for (std::size_t e = 0; e < ends.rows(); ++e) {
      const auto na = static_cast<std::size_t>(ends.row(e)[0]), nb = static_cast<std::size_t>(ends.row(e)[1]);
      double dir[3] = {0, 0, 0}, len = 0, s = 0;
      for (int q = 0; q < d; ++q) {
        dir[q] = X[nb * d + q] - X[na * d + q];
        len += dir[q] * dir[q];
      }
      len = std::sqrt(len);
      for (int q = 0; q < d; ++q) s += dir[q] / len * ((x1[nb * d + q] - X[nb * d + q]) - (x1[na * d + q] - X[na * d + q]));
      t[e] = k[e] * s;
    }
  }

  void detection_configuration(StepContext& c) override {
    State& st = c.state;
    const int d = d_;
    const double a = (1 - c.theta) * c.h;
    const double* x = st.field(C::nodes, N::position).data(Depth::begin);
    const double* v = st.field(C::nodes, C::velocity).data(Depth::begin);
    double* p = st.field(C::nodes, N::detection_position).data();
    double* travel = st.field(C::nodes, N::travel).data();
    double g = 0;
    for (double gk : c.gravity) g += gk * gk;
    g = std::sqrt(g);
    for (std::size_t i = 0; i < st.set(C::nodes).rows(); ++i) {
      double v2 = 0;
      for (int k = 0; k < d; ++k) {
        p[i * d + k] = x[i * d + k] + a * v[i * d + k];
        v2 += v[i * d + k] * v[i * d + k];
      }
      travel[2 * i] = 2 * c.h * std::sqrt(v2) + c.h * c.h * g;
      travel[2 * i + 1] = 0;
    }
  }

  bool compact_inverse(const State&, std::size_t, double*) const override { return false; }

  void apply_inverse(const State& st, std::size_t body, int columns, const double* in, double* out) const override {
    const Body& B = body_[index_of(st, body)];
    const long n = static_cast<long>(B.nodes) * d_;
    Eigen::Map<const Eigen::MatrixXd> rhs(in, n, columns);
    Eigen::Map<Eigen::MatrixXd>(out, n, columns) = B.lhs.solve(rhs);
  }

 private:
  struct Body {
    std::size_t first = 0, nodes = 0;
    Eigen::MatrixXd K;
    Eigen::LLT<Eigen::MatrixXd> lhs;
  };

  std::size_t index_of(const State&, std::size_t body) const {
    for (std::size_t i = 0; i < bodies_.size(); ++i)
      if (bodies_[i] == body) return i;
    throw std::logic_error("chain_theta: body " + std::to_string(body) + " is not a chain");
  }

  /// K from the springs (about the rest configuration) and LHS = M + h²θ²K, factorised.
  void factorise(const State& st, double theta) {
    if (theta == theta_) return;
    theta_ = theta;
    const int d = d_;
    const double* X = st.field(C::nodes, C::rest_position).data();
    const double* m = st.field(C::nodes, C::mass).data();
    const Field& ends = st.field(C::springs, C::ends);
    const double* k = st.field(C::springs, C::stiffness).data();
    body_.assign(bodies_.size(), Body{});
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
      const BodyRows r = st.body(bodies_[i]);
      Body& B = body_[i];
      B.first = r.first_node;
      B.nodes = r.nodes;
      const long n = static_cast<long>(r.nodes) * d;
      B.K = Eigen::MatrixXd::Zero(n, n);
      for (std::size_t e = r.first_element; e < r.first_element + r.elements; ++e) {
        const long a = static_cast<long>(ends.row(e)[0] - static_cast<double>(r.first_node));
        const long b = static_cast<long>(ends.row(e)[1] - static_cast<double>(r.first_node));
        Eigen::VectorXd dir(d);
        for (int q = 0; q < d; ++q) dir[q] = X[(r.first_node + b) * d + q] - X[(r.first_node + a) * d + q];
        dir.normalize();
        const Eigen::MatrixXd kee = k[e] * dir * dir.transpose();
        B.K.block(a * d, a * d, d, d) += kee;
        B.K.block(b * d, b * d, d, d) += kee;
        B.K.block(a * d, b * d, d, d) -= kee;
        B.K.block(b * d, a * d, d, d) -= kee;
      }
      Eigen::MatrixXd lhs = h_ * h_ * theta * theta * B.K;
      for (long j = 0; j < n; ++j) lhs(j, j) += m[r.first_node + static_cast<std::size_t>(j / d)];
      B.lhs.compute(lhs);
    }
  }

  double h_;
  int d_ = 3;
  double theta_ = -1;
  int model_ = -1;
  std::vector<std::size_t> bodies_;
  std::vector<Body> body_;
};

MOREAU_REGISTER(ChainTheta, "chain_theta")

}  // namespace

MOREAU_PLUGIN_LIBRARY("moreau_integrator_chain_theta")
