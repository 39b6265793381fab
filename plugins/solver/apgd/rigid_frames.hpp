#pragma once
// W = H M⁻¹ Hᵀ (+ the laws' compliance on the diagonal) for 3D rigid bodies, packed by what
// H is made of rather than by its numbers: a contact's rows are the frame E (rows n, t, s)
// and the lever arms r₀, r₁ of its two sides, H_s = ±[E, rows r_s × e_i], and a body's
// inverse mass is 1/m on the translations and I⁻¹ (symmetric 3 × 3, world axes) on the
// rotations. Per contact 15 doubles (E, r₀, r₁) instead of the 36 of ScaledFactor's H̃, and
// per moving body 7 (1/m, I⁻¹): the product, memory-bound at 10⁴ spheres and more, reads
// 2.4 times less per contact. One product:
//   pass 1, per contact: f = Eᵀ x_α (the impulse in world axes); each moving side's body
//           gets ±(f, r_s × f) in z (its impulse and angular impulse);
//   per moving body:     z ← (z_t/m, I⁻¹ z_r) (its velocity change);
//   pass 2, per contact: out_α = E (u₀ − u₁), u_s = v_s + ω_s × r_s (the point's velocity).
// prepare() reads r_s back from H (r = ½ Σ_i e_i × (r × e_i), E orthonormal) and packs only
// when every block is of that form to rounding and every moving body's inverse mass is
// 1/m I₃ ⊕ I⁻¹; otherwise it returns false and the caller packs H̃ (ScaledFactor). The
// product is W's to rounding (ApgdFactored.RigidFramesMultiplyByW).
#include <Eigen/Core>
#include <moreau/contact_problem.hpp>
#include <vector>

namespace moreau::apgd {

class RigidFrames {
 public:
  /// Packs f (d = 3, k = 6) when it has the rigid form above; false, nothing packed, else.
  /// A later call packs another problem into the same arrays (their memory kept).
  bool prepare(int d, const BodyFactor& f);
  /// out = W x (sizes 3·nc).
  void multiply(const Eigen::VectorXd& x, Eigen::VectorXd& out);
  /// W's diagonal (+ the compliance).
  Eigen::VectorXd diagonal() const;

 private:
  std::size_t nc_ = 0;
  std::vector<double> contact_;  ///< nc × 15: E (row-major, rows n t s), r₀, r₁
  std::vector<int> body_;        ///< nc × 2: the moving body's compact index, −1 for a fixed body
  std::vector<double> mass_;     ///< moving bodies × 7: 1/m, I⁻¹ (xx yy zz xy xz yz)
  std::vector<double> z_;        ///< moving bodies × 6: impulses, then velocity changes (scratch)
  std::vector<double> diag_;     ///< 3·nc or empty: the compliance
  std::vector<int> compact_;     ///< prepare()'s scratch: per body of the factor its compact index
};

}  // namespace moreau::apgd
