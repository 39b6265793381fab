#pragma once
// Swept detection of fast pairs (docs/contacts.md, "Fast bodies").
//
// Contacts are detected on the predicted configuration q_θ = q⁻ + (1−θ)h v⁻, and the
// θ-scheme moves every body by (1−θ)h v⁻ whatever the contact impulses. A body that moves
// in a step further than a shape is thick may be predicted past a thin wall (or deep in
// it, its normal flipped), or beside a wall it will hit later in the step (a face clipped
// against nothing): detection at q_θ then sees nothing to stop it. Such pairs (`fast`)
// are followed from the start configuration q⁻ along the step's motion by conservative
// advancement (each advance is the distance over a bound of the approach speed, so it
// never jumps over a contact); if they touch within the step, at time t, the contacts of
// that moment are carried to q_θ (time T = (1−θ)h, before or after t) to first order
// (gap + (T − t) u_n, normal kept), and flagged `swept` so the solve keeps them from
// ending the step overlapping (`swept_shift`). Pairs that are not fast, or do not touch
// within the step, keep the contacts of q_θ: resting and slow contacts are exactly as
// without this.
//
// The motion within the step is read from the node sets: `position` and the rotation
// (`angle` / `orientation`) at the start of the step, and `velocity`, `angular_velocity`
// (rigid nodes have them). A modelization whose nodes lack velocities is taken as still
// over the step, one without `position` never swept.
//
// Contactors on meshes (bodies of more than one node: a `point` on a node, an `edge` or
// `face` on a facet) are never swept: a facet is placed by several nodes, not by one pose
// advanced along (v, ω), and points and facets have no thickness to stop short of (a
// quarter of the thinner half width is 0). Their pairs keep the contacts of q_θ, found
// within the alert distance grown by each node's travel in the step (contactor_sweep_).
#include <algorithm>
#include <moreau/detector.hpp>
#include <moreau/state.hpp>
#include <vector>

#include "placement.hpp"

namespace moreau::kernel {

struct Contactor;
struct ContactModel;

/// A body's pose (position 3, rotation 4: 2D angle in [0]) after moving for a time t from
/// position x and rotation q at velocity v and angular velocity w (world frame): x + t v,
/// and the rotation advanced by t w (3D: exp(t w / 2) ⊗ q to first order, renormalised).
void advance_pose(int dim, const double* x, const double* v, const double* q, const double* w, double t, double* pose);

/// The shift of a swept contact: never weaker than what keeps it from ending the step
/// overlapping. Its gap at q_θ is g + θ h u_n⁺ at the step's end, so a negative g needs
/// u_n⁺ ≥ −g/(θh): the body ends touching, leaving at most at the speed it came
/// ((1−θ)/θ of it), so no energy is gained.
inline double swept_shift(double law_shift, double gap, double theta, double h) {
  return gap < 0 && theta > 0 ? std::min(law_shift, gap / (theta * h)) : law_shift;
}

class SweptDetection {
 public:
  /// Per step, before the narrow phase: h, T = (1−θ)h and the nodes' start state.
  void begin_step(const std::vector<Contactor>& contactors, const std::vector<ContactModel>& models, const State& state,
                  double theta, double h);
  /// Whether the pair may move, relative to each other, by more than half the sum of the
  /// shapes' half widths in a step (then q_θ may lie past, deep in or beside one).
  bool fast(int i, int j) const;
  /// Follows the fast pair (first, second) from q⁻. True when they touch within the step:
  /// `out` then holds the contacts carried to q_θ and `start_gap` each one's gap where
  /// they touched if that is the start configuration (else the pair's distance there, > 0).
  /// False: they stay apart all step (q_θ's own contacts stand).
  bool detect(int dim, const Detector& detector, const std::vector<Contactor>& contactors, int first, int second,
              double alert, std::vector<ContactPoint>& out, std::vector<double>& start_gap);
  /// Pairs whose advancement gave up (the iteration limit) and kept q_θ's contacts.
  long unconverged() const { return unconverged_; }

 private:
  void contactor_pose(int contactor, double t, double* pose) const;
  double approach_speed(int i, int j) const;
  /// A lower bound of the distance between contactors i and j at poses pa, pb.
  double distance_bound(const Shape& a, int i, const double* pa, const Shape& b, int j, const double* pb) const;

  int dim_ = 3;
  double step_ = 0;         // h
  double travel_time_ = 0;  // T = (1−θ)h
  // Per contactor (computed once): half width, radius (of a ball about its own origin that
  // holds it) and reach (largest distance of its shape from its body's origin), m.
  std::vector<double> half_width_, radius_, reach_;
  /// Per contactor: on a body of more than one node (a mesh), hence never swept.
  std::vector<char> on_mesh_;
  /// Per modelization, its nodes at the start of the step (Depth::begin): position,
  /// rotation, velocity, angular velocity; null where the set has no such field.
  struct Nodes {
    const double *x = nullptr, *q = nullptr, *v = nullptr, *w = nullptr;
  };
  std::vector<Nodes> nodes_;
  const std::vector<Contactor>* contactors_ = nullptr;
  /// A contactor's node: its position, velocity (zero if unknown) and angular velocity.
  const double* x_of(int i) const;
  const double* v_of(int i) const;
  const double* w_of(int i) const;
  std::vector<ContactPoint> scratch_;
  long unconverged_ = 0;
};

}  // namespace moreau::kernel
