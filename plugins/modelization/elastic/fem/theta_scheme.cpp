#include "theta_scheme.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace moreau::fem {

LinearThetaScheme::LinearThetaScheme(const SparseMatrix& M, const SparseMatrix& C, const SparseMatrix& K, double h,
                                     double theta, DofPartition partition, CholeskyBackend backend)
    : h_(h), theta_(theta), partition_(std::move(partition)), K_(K), factor_(backend) {
  if (!(h > 0) || !std::isfinite(h)) throw std::invalid_argument("θ-scheme: the time step must be > 0");
  if (!(theta >= 0.5 && theta <= 1)) throw std::invalid_argument("θ-scheme: θ must lie in [0.5, 1]");
  const SparseMatrix lhs = theta_lhs(M, C, K, h, theta);
  R_ = M - (h * (1 - theta)) * C - (h * h * theta * (1 - theta)) * K;
  lhs_fc_ = partition_.coupling_block(lhs);
  factor_.factorize(partition_.free_block(lhs));
}

Eigen::VectorXd LinearThetaScheme::free_velocity(const Eigen::VectorXd& u, const Eigen::VectorXd& v,
                                                 const Eigen::VectorXd& f_begin, const Eigen::VectorXd& f_end,
                                                 const Eigen::VectorXd& v_imposed) const {
  if (v_imposed.size() != static_cast<Eigen::Index>(partition_.constrained().size()))
    throw std::invalid_argument("θ-scheme: " + std::to_string(partition_.constrained().size()) +
                                " imposed velocities expected, got " + std::to_string(v_imposed.size()));
  const Eigen::VectorXd rhs = R_ * v - h_ * (K_ * u) + h_ * ((1 - theta_) * f_begin + theta_ * f_end);
  const Eigen::VectorXd b = partition_.free_part(rhs) - lhs_fc_ * v_imposed;
  return partition_.combine(factor_.solve(b), v_imposed);
}

Eigen::VectorXd LinearThetaScheme::impulse_response(const Eigen::VectorXd& p) const {
  return partition_.combine(factor_.solve(partition_.free_part(p)),
                            Eigen::VectorXd::Zero(static_cast<Eigen::Index>(partition_.constrained().size())));
}

Eigen::MatrixXd LinearThetaScheme::impulse_responses(const Eigen::MatrixXd& P) const {
  const auto& free = partition_.free();
  Eigen::MatrixXd Pf(static_cast<Eigen::Index>(free.size()), P.cols());
  for (std::size_t i = 0; i < free.size(); ++i) Pf.row(static_cast<Eigen::Index>(i)) = P.row(free[i]);
  const Eigen::MatrixXd Vf = factor_.solve_columns(Pf);
  Eigen::MatrixXd V = Eigen::MatrixXd::Zero(P.rows(), P.cols());
  for (std::size_t i = 0; i < free.size(); ++i) V.row(free[i]) = Vf.row(static_cast<Eigen::Index>(i));
  return V;
}

Eigen::VectorXd LinearThetaScheme::displacement(const Eigen::VectorXd& u, const Eigen::VectorXd& v,
                                                const Eigen::VectorXd& v_next) const {
  return u + h_ * ((1 - theta_) * v + theta_ * v_next);
}

}  // namespace moreau::fem
