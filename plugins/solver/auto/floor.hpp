#pragma once
// The floor of `auto`'s slices (docs/solvers.md "Guarantee"): what bounds auto's work by K
// times the least work of a member, whatever the heuristic rule does with the rest.
//
// Each floor member (NLGS, APGD, Newton's own run and ADMM when a factorisation fits) keeps
// its own run, which goes on from slice to slice as it would alone (its iterate, its
// state), so that after w units of work in auto it has done what it does alone in w. A
// member whose own run is more than one of its iterations behind (total work)/K_i gets a
// slice of it, before any other slice; the slices the heuristic rule picks are cut so that
// they do not take the total past K_i·(w_i + s_i) of a floor member i (w its own-run work,
// s one of its iterations). So at every choice, total ≤ K_j·(w_j + s_j) for the member j
// that alone needs the least work L_j, whose run is then below L_j − s_j: total < K_j·L_j,
// and the solve ends, at the latest, in the slice in which j's own run reaches the
// tolerance. Hence auto's work ≤ K_j·(L_j + s_j) + one slice (at least the slice's
// minimum: 5 iterations, or Newton's 4-step probe) + D, D the work of rule 2b's Newton steps
// (docs/solvers.md, 2b: a few steps from a warm start within 1e-3, each but the last
// gaining 10×), which the floor leaves out of the total it shares (floor_slice()). K_i =
// member_k(): the floor takes at most Σ 1/K_i of the work and the heuristic rule the rest.
#include <array>
#include <limits>

namespace moreau::auto_floor {

/// K of a floor member. Without a factorisation (NLGS and APGD only): 4 each (the floor
/// takes half the work). With one: 4.5 for NLGS and APGD, 8 for Newton's own run and ADMM
/// (the floor takes 2/4.5 + 2/8 = 69 %). Each Newton or ADMM step is a factorisation, so
/// their K·(w + s) grows in large steps and the floor pays them late anyway (ski rental);
/// the cheap members' runs get the larger share, since they are the least members on most
/// problems and the rule's slices from the best iterate restart APGD's acceleration. On the
/// whole reduced corpus (docs/solvers.md "Guarantee") this took the worst ratio from 8.09
/// (1e-4) and 7.86 (1e-8) with K = 8 for all four to 4.93 and 5.12 with 5 and 8; K = 5 for
/// all four (the floor takes 80 %) measured 6.95 and 7.54, 5 and 12 5.11 and 5.20, 6 and 8
/// 5.61 and 6.08, 4 and 8 5.28 and 5.45. With rule 2b's steps outside the floor's total
/// (branch i15-k4), 5 and 8 → 4.5 and 8: corpus worst 3.56 / 5.04 → 3.88 / 4.69, the
/// ctest's pairs 4.69 / 5.06 → 4.19 / 4.30 (the worst pair at 1e-8, APGD's on the dense
/// disks, sits at APGD's K); 4 and 8 4.41 / 4.59 and 5.29 on the ctest's pairs, 4.5 and 7
/// 4.67 (within 2×: 116 / 102 of 129 / 125), 4.5 and 9 4.79, 5 and 7 5.07, 5 and 10 5.06,
/// 5.5 and 7 5.71, 4 and 10 4.95.
inline double member_k(bool factorisation, bool factorises) {
  if (!factorisation) return 4.0;
  return factorises ? 8.0 : 4.5;
}

/// One floor member as the floor sees it.
struct Run {
  bool in = false;    ///< a floor member on this problem, not yet at its iteration cap
  double spent = 0;   ///< work of its own run in this solve
  double step = 0;    ///< the work of its next iteration (its probe when untried)
  double k = 4;       ///< its K (member_k())
};

/// The floor member furthest behind total/K by more than one of its iterations (−1: none).
template <std::size_t N>
int behind(const std::array<Run, N>& runs, double total) {
  int who = -1;
  double lag = 0;
  for (std::size_t i = 0; i < N; ++i) {
    const Run& r = runs[i];
    if (!r.in) continue;
    const double l = total / r.k - (r.spent + r.step);
    if (l >= 0 && (who < 0 || l > lag)) who = static_cast<int>(i), lag = l;
  }
  return who;
}

/// The most work a slice of member `who` (a floor member or not) may take now without
/// putting another floor member behind: K·(w + s) − total over the others (∞: no other).
template <std::size_t N>
double room(const std::array<Run, N>& runs, double total, int who) {
  double least = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < N; ++i)
    if (runs[i].in && static_cast<int>(i) != who) least = std::min(least, runs[i].k * (runs[i].spent + runs[i].step) - total);
  return least;
}

}  // namespace moreau::auto_floor
