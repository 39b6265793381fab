// What `auto` remembers over the solves of a run (`remember`): each member's work per contact
// (Memory), the incumbent that goes first, the challenger tried on the incumbent's budget, and
// learn(), which updates the memory after a solve. The memory is saved with every frame
// (register.cpp).
#include "auto.hpp"

namespace moreau::auto_solver {

/// With `remember`: whether this solve starts with a member other than NLGS (the
/// incumbent() of the members available on a problem of this size).
bool Auto::starts_with_another_member(bool direct) const {
  if (!remember_) return false;
  int best = -1;
  for (int k = 0; k < member_count; ++k)
    if ((k == nlgs_member || k == apgd_member || direct) && memory_[k].cost > 0 && (best < 0 || memory_[k].cost < memory_[best].cost))
      best = k;
  return best > nlgs_member;
}

/// The member with the lowest remembered work per contact among those available; −1 when
/// none is known yet.
int Auto::incumbent(const std::array<MemberState, member_count>& m) const {
  int best = -1;
  for (int k = 0; k < member_count; ++k)
    if (m[k].available && memory_[k].cost > 0 && (best < 0 || memory_[k].cost < memory_[best].cost)) best = k;
  return best;
}

/// A member to try before the incumbent on this solve: one whose turn has come (untried
/// ones first, then the lowest remembered work) and whose first iterations fit in the
/// incumbent's work. −1: none.
int Auto::challenger(const std::array<MemberState, member_count>& m, int inc) {
  const double budget = memory_[inc].cost;
  int best = -1;
  for (int k = 0; k < member_count; ++k) {
    if (k == inc || !m[k].available || memory_[k].next_probe > solve_index_) continue;
    if (k == nlgs_member && beyond_caches()) continue;  // its rate shows after ~10 sweeps (beyond_caches())
    if (k == newton_member) continue;  // from the best iterate: only useful after another member
    // Its first iterations' work per contact: remembered, or estimated for one not yet
    // tried (Newton and ADMM: a factorisation each; on light steps more than a whole solve).
    const bool factors = k == newton_start_member || k == admm_member;
    const double step = memory_[k].step > 0 ? memory_[k].step
                        : factors           ? newton_step_estimate() / nc_
                        : k == apgd_member  ? (costs_.product + costs_.error) / nc_
                                            : costs_.sweep / nc_;
    const double first_steps = (factors ? 2.0 : 5.0) * step;
    if (first_steps > budget) {  // cannot show anything within the budget
      memory_[k].interval = std::min<long>(2 * memory_[k].interval, 256);
      memory_[k].next_probe = solve_index_ + memory_[k].interval;
      continue;
    }
    if (best < 0 || memory_[k].cost < memory_[best].cost) best = k;
  }
  return best;
}

/// The lowest remembered work of a member other than NLGS, for this problem's size.
double Auto::other_cost() const {
  double c = 0;
  for (int k = 1; k < member_count; ++k)
    if (memory_[k].cost > 0 && (c == 0 || memory_[k].cost < c)) c = memory_[k].cost;
  return remember_ ? c * nc_ : 0;
}

/// After a solve: each member's remembered work per contact follows what this solve showed
/// (exponential average): the work of the member that converged, or the work extrapolated
/// at its rate for one that did not; only for runs from the warm start (a fair measure),
/// and for a winner not yet remembered (at its own work) also when it finished from
/// another member's iterate.
void Auto::learn(const std::array<MemberState, member_count>& m) {
  at_rest_ = best_err_ <= tol_ && total_ <= 2;  // the warm start (after at most one sweep) was the answer
  // A step that the remembered member led and another member finished (the incumbent
  // did not within its budget): that member is tried first at the next solve (its wait
  // back to 4 solves). Only a run from the warm start teaches the memory, so a member
  // that only ever finishes after the incumbent is never measured, and its lost
  // challenges had pushed its turn to every 256 solves: on silo_janssen_2d (1e-4, from
  // step 2609 of `auto`'s run) Newton led all of 200 steps while APGD, remembered at 10×
  // its cost since a hard step, finished the steps Newton did not.
  if (incumbent_ >= 0 && winner_ >= 0 && winner_ != incumbent_ && winner_ != challenger_) {
    memory_[winner_].interval = 4;
    memory_[winner_].next_probe = std::min(memory_[winner_].next_probe, solve_index_ + 1);
  }
  // A solve that its first member finished at its first check (a warm start that was
  // already the answer, or no contact closing) says nothing of the members' costs.
  // But a challenger that wins at its first check is learnt at what it took: it was tried
  // on the incumbent's budget and did the step for less (block_on_incline_3d: APGD won
  // every 4th step at its check, 895 units against NLGS's sweep, 1972, and NLGS stayed
  // remembered at its cold first step's 4010 a contact, so it was tried again and again).
  if (winner_ >= 0 && winner_ != challenger_ && m[winner_].iterations <= 1 && m[winner_].slices <= 1) return;
  for (int k = 0; k < member_count; ++k) {
    const MemberState& s = m[k];
    if (s.slices == 0) continue;
    Memory& mem = memory_[k];
    if (s.per_iteration > 0 && std::isfinite(s.per_iteration)) mem.step = s.per_iteration / nc_;
    // The winner also when it finished from another member's iterate, if it has no
    // memory yet, at its own work (below what it takes from the warm start: as the
    // remembered member it then goes on past its budget and is learnt at what it took;
    // one already remembered keeps its memory, as before: learnt so after hard steps too,
    // masonry_arch_2d at 1e-8 took 6 % more work over its 6000 steps). Before, it was not learnt: on
    // mortar_wall_2d at 1e-8 the cold step's winner APGD finished from NLGS's iterate and
    // only ADMM, which failed (its own run, clean), was remembered, at its bounded need
    // 1.3·10⁸ a contact; that was the next step's challenger's budget, and NLGS ran it
    // alone for 1430 sweeps (12 ms) where APGD takes 386 iterations. (At the solve's work
    // less the lost own runs instead, 1.6·10⁴ a contact there against 1.1·10⁴, the lost
    // challenges of Newton and ADMM on that budget left the 300 steps' work 8 % above main.)
    if (!s.clean && (k != winner_ || mem.cost > 0)) continue;
    const double c = (k != winner_ ? bounded_need(s, k) : s.spent) / nc_;
    if (c > 0 && std::isfinite(c)) mem.cost = remembered(mem.cost, c);
  }
}

/// The work a member that did not converge is remembered at: its need extrapolated at its
/// last rate, but at most what its run would take to its iteration cap from where it
/// stopped (a slice that gained next to nothing, ADMM's first step on a 650-contact step
/// of wet_pile_3d, extrapolated to 7·10²⁰ units a contact).
double Auto::bounded_need(const MemberState& s, int k) const {
  if (!(s.per_iteration > 0)) return s.need;
  const double cap = s.spent + static_cast<double>(std::max<long>(0, member_max(k) - s.iterations)) * s.per_iteration;
  return std::min(s.need, cap);
}

}  // namespace moreau::auto_solver
