#pragma once
// The floor of `auto`'s slices (docs/solvers.md "Guarantee"): what bounds auto's work by K
// times the least work of a member, whatever the heuristic rule does with the rest.
//
// Each floor member (NLGS, APGD, Newton's own run and ADMM when a factorisation fits) keeps
// its own run, which goes on from slice to slice as it would alone (its iterate, its
// state), so that after w units of work in auto it has done what it does alone in w. A
// member whose own run is more than one of its iterations behind (total work)/K gets a
// slice of it, before any other slice; the slices the heuristic rule picks are cut so that
// they do not take the total past K·(w + s) of a floor member (w its own-run work, s one of
// its iterations). So at every choice, total ≤ K·(w_j + s_j) for the member j that alone
// needs the least work L_j, whose run is then below L_j − s_j: total < K·L_j, and the
// solve ends, at the latest, in the slice in which j's own run reaches the tolerance.
// Hence auto's work ≤ K·L_j + one slice (at least the slice's minimum: 5 iterations, or
// Newton's 4-step probe). K = floor_k: twice the floor members, so that the floor takes at
// most half of the work and the heuristic rule the rest.
#include <array>
#include <limits>

namespace moreau::auto_floor {

/// K for `members` floor members: 2 per member (NLGS and APGD: 4; with Newton and ADMM: 8).
inline double floor_k(int members) { return 2.0 * members; }

/// One floor member as the floor sees it.
struct Run {
  bool in = false;    ///< a floor member on this problem, not yet at its iteration cap
  double spent = 0;   ///< work of its own run in this solve
  double step = 0;    ///< the work of its next iteration (its probe when untried)
};

/// The floor member furthest behind total/K by more than one of its iterations (−1: none).
template <std::size_t N>
int behind(const std::array<Run, N>& runs, double total, double k) {
  int who = -1;
  double lag = 0;
  for (std::size_t i = 0; i < N; ++i) {
    const Run& r = runs[i];
    if (!r.in) continue;
    const double l = total / k - (r.spent + r.step);
    if (l >= 0 && (who < 0 || l > lag)) who = static_cast<int>(i), lag = l;
  }
  return who;
}

/// The most work a slice of member `who` (a floor member or not) may take now without
/// putting another floor member behind: K·(w + s) − total over the others (∞: no other).
template <std::size_t N>
double room(const std::array<Run, N>& runs, double total, double k, int who) {
  double least = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < N; ++i)
    if (runs[i].in && static_cast<int>(i) != who) least = std::min(least, k * (runs[i].spent + runs[i].step) - total);
  return least;
}

}  // namespace moreau::auto_floor
