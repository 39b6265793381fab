#pragma once
// The order of an NLGS sweep. By default (`fixed_last`) the contacts with a fixed body
// (walls, floors: inverse mass zero, body −1 in LocalProblem::factor) come after all the
// others, each group in the given order. A sweep ends with the contacts it updated last
// solved exactly against the final state of the sweep; the contacts visited earlier carry
// the changes made after their visit. Swept last, the wall contacts, which carry the
// whole weight of a pile, end every sweep exactly solved, so grains do not sink into walls
// by the residual of the stopping test. LMGC90 gets this by its contact list, built type
// by type with the grain–wall types (DKJCx, SPPLx) after the grain–grain ones; moreau's
// given order (the broad phase's) puts the wall contacts first. Measured on the 40-disk
// deposit of tests/validation/test_stopping.cpp (nlgs, 1e-4, step 400): the median overlap
// of the loaded wall contacts went from 9e-3 µm to 3e-12 µm, the grains' from 5e-4 to
// 8e-4 µm (no test checks this yet). Without the factor (an FCLib file) the bodies are
// unknown and the given order is kept.
#include <Eigen/Core>
#include <algorithm>
#include <moreau/contact_problem.hpp>
#include <numeric>
#include <vector>

namespace moreau::nlgs {

/// 0, 1, …, nc − 1 with the contacts touching a fixed body moved to the end (stable).
inline void fixed_last_order(const LocalProblem& P, std::vector<Eigen::Index>& order) {
  order.resize(static_cast<std::size_t>(P.contacts()));
  std::iota(order.begin(), order.end(), Eigen::Index{0});
  if (!P.factor.present()) return;
  const auto& body = P.factor.body;
  std::stable_partition(order.begin(), order.end(), [&](Eigen::Index a) {
    return body[static_cast<std::size_t>(2 * a)] >= 0 && body[static_cast<std::size_t>(2 * a + 1)] >= 0;
  });
}

}  // namespace moreau::nlgs
