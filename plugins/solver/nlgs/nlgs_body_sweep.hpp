#pragma once
// NLGS exchanging impulses through body velocities (LMGC90's variant without W blocks):
// with W = H M⁻¹ Hᵀ (LocalProblem::factor), contact α's velocity is
//   u_α = q_α + Σ_s H_αs Δv_b(α,s),   Δv = M⁻¹ Hᵀ r,
// so a contact update reads two body velocity changes and writes them back after its
// one-contact solve, instead of reading every neighbour's impulse through a row of W.
// The cost per update is fixed (two d×k blocks each way) whatever the coordination
// number, and the hot data is one packed record per contact, read in sweep order
// (Bullet's solver-body idea: the solver packs its own data and writes r back).
//
// A frictionless problem (every μ = 0) is the normal problem alone (r_t = 0): records
// keep the normal row only, and when no normal row turns a body (spheres and disks: the
// normal passes through the centres) the angular columns go too, so a record shrinks
// from 85 doubles (3D) to 15 and a scene pays nothing for friction or rotation it lacks.
// With friction, when every body's inverse mass is one scalar per block (spheres, disks),
// the record keeps those scalars instead of G = M⁻¹Hᵀ: 53 doubles instead of 85.
#include <Eigen/Core>
#include <moreau/contact_problem.hpp>
#include <vector>

#include "local_solvers.hpp"

namespace moreau::nlgs {

class BodySweeper {
 public:
  /// Packs the records from P.factor (which must be present) and sets Δv from r.
  void prepare(const LocalProblem& P, const Eigen::VectorXd& r);
  /// Only the records' layout (record_size()), not the records: prepare() = layout() then
  /// pack(), for a caller that decides from the size whether to sweep at all (`auto`).
  void layout(const LocalProblem& P);
  /// Packs the records of the problem given to layout() and sets Δv from r.
  void pack(const LocalProblem& P, const Eigen::VectorXd& r);
  /// r_α ← ω local(α) + (1 − ω) r_α for α in `order`, updating Δv as it goes.
  void sweep(Eigen::VectorXd& r, double omega, const std::vector<Eigen::Index>& order);
  /// The one-contact solver used by the sweeps (exact by default).
  void set_local(const LocalOptions& o) { local_ = o; }
  /// u = q + H Δv with Δv recomputed from r (increments accumulated over many sweeps
  /// would drift by rounding; the error check must see the true u = W r + q).
  void velocities(const Eigen::VectorXd& r, Eigen::VectorXd& u);
  /// Sets Δv from another r (records kept): sweeps then continue from that r.
  void reset_velocities(const Eigen::VectorXd& r);
  /// Doubles per contact record (what a sweep reads per contact): for cost models.
  std::size_t record_size() const { return stride_; }
  /// Whether records can be made for contact dimension d and k unknowns per body: rigid
  /// bodies (2D: 3, 3D: 6); layout() throws otherwise.
  static bool supports(int d, int k) { return (d == 2 && k == 3) || (d == 3 && k == 6); }
  /// The most doubles a record can take for d and k, whatever μ and the inverse masses: the
  /// bound of record_size() for a caller that decides before layout() (`auto`).
  static std::size_t largest_record_size(int d, int k);
  /// Whether the records carry M⁻¹Hᵀ blocks (bodies whose inverse mass is not one scalar per
  /// block: boxes, polygons, clusters), whose Δv updates are dense products: for cost models.
  bool dense_inverse_mass() const { return !iso_ && pd_ == d_ && pk_ == k_; }

 private:
  int d_ = 3, k_ = 6;         ///< the problem's: contact dimension, unknowns per body
  int pd_ = 3, pk_ = 6;       ///< packed: rows kept per contact (d, or 1 frictionless), columns per body
  bool iso_ = false;          ///< every moving body's M⁻¹ is one scalar per block: records keep those, not G
  /// Where H₀ and G₀ start in a record, and its doubles, for pd rows, pk columns and
  /// scalar inverse masses or not (the layout of rec_ below).
  struct Offsets {
    int H, G;
    std::size_t stride;
  };
  static Offsets offsets(int pd, int pk, bool iso);
  int off_H_ = 0, off_G_ = 0; ///< where H₀ and G₀ start in a record
  std::size_t stride_ = 0;    ///< doubles per record
  std::vector<char> layout_checked_;  ///< layout()'s scratch: per body, its inverse mass checked
  /// Per contact: A (pd×pd), q (pd), μ, [iso: m_t m_r of each side], H₀ H₁ (pd×pk),
  /// [not iso: G₀ G₁ = M⁻¹Hᵀ (pk×pd)].
  std::vector<double> rec_;
  std::vector<int> body_;     ///< per contact, 2 indices into dv_ blocks; −1: the body does not move
  LocalOptions local_;        ///< the one-contact solver
  std::vector<double> dv_;    ///< moving bodies × pk: velocity change due to r, numbered by first use
  const LocalProblem* problem_ = nullptr;  ///< for the full u when packed (tangential rows)
  std::vector<double> full_impulse_, full_dv_;  ///< all bodies × k: Hᵀ r and M⁻¹ Hᵀ r for that u
};

}  // namespace moreau::nlgs
