#pragma once
// W = H M⁻¹ Hᵀ (+ the laws' compliance on the diagonal) packed for repeated products by
// W, the hot loop of APGD in the time-stepper (W is never built there). Each moving
// body's inverse mass is split once per solve as M⁻¹ = L Lᵀ (Cholesky; for a sphere or a
// disk L = diag(√m_t, √m_r)) and folded into its contacts' blocks, H̃ = H L, so that
//   W x = H̃ (H̃ᵀ x)   (+ diagonal ∘ x)
// is two streaming passes over one packed array of contact blocks, in contact order, with
// a k-vector per moving body in between: no pass over the bodies' k × k inverses (the
// generic multiply_w reads 36 doubles per 3D body each product) and no indirection through
// the body index of a fixed body. The dimensions are compile-time constants (2D: d = 2,
// k = 3; 3D: d = 3, k = 6), so the inner loops unroll. Moving bodies are numbered by first
// use in contact order, so the body vectors neighbouring contacts touch sit together.
#include <Eigen/Core>
#include <moreau/contact_problem.hpp>
#include <vector>

namespace moreau::apgd {

class ScaledFactor {
 public:
  /// Packs f (rigid bodies: d = 2, k = 3 or d = 3, k = 6). False, with nothing packed,
  /// for another shape or when an inverse mass is not positive semi-definite to rounding
  /// (L Lᵀ would not give it back): the caller then multiplies with multiply_w. A later
  /// call packs another problem into the same arrays (their memory kept).
  bool prepare(int d, const BodyFactor& f);
  /// out = W x (sizes d·nc).
  void multiply(const Eigen::VectorXd& x, Eigen::VectorXd& out);
  /// W's diagonal: the squared norms of the rows of H̃ (+ the compliance).
  Eigen::VectorXd diagonal() const;
  /// Doubles read per contact and product (both passes): for cost models.
  static double doubles_per_contact(int d) { return d == 2 ? 2 * 2 * 2 * 3 : 2 * 2 * 3 * 6; }

 private:
  int d_ = 3, k_ = 6;
  std::size_t nc_ = 0;
  std::vector<double> H_;       ///< nc × 2 × (d × k), row-major: H̃ = H L per contact side (zero: fixed body)
  std::vector<int> body_;       ///< nc × 2: the moving body's compact index, −1 for a fixed body
  std::vector<double> z_;       ///< moving bodies × k: H̃ᵀ x (scratch)
  std::vector<double> diag_;    ///< d·nc or empty: the compliance
  // prepare()'s scratch, kept with its capacity for the next problem
  std::vector<int> compact_;    ///< per body of the factor: its compact index, −1 when no contact moves it
  std::vector<double> L_;       ///< per moving body: its factor L (k × k, row-major, lower)
  std::vector<char> diagonal_;  ///< per moving body: L is diagonal
};

}  // namespace moreau::apgd
