// The grid broad phase against brute force: every overlapping pair of interacting
// contactors of different bodies, once, sorted; whatever the cell (automatic, given small,
// given large), with long walls kept out of the cell size and half-spaces.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <moreau/broadphase.hpp>
#include <random>

#include "sim.hpp"

namespace {

using Pairs = std::vector<std::pair<int, int>>;

Pairs brute_force(const moreau::BroadPhaseInput& in) {
  Pairs out;
  const std::size_t n = in.body.size();
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      if (in.body[i] == in.body[j] || !in.interacts[in.group[i] * in.groups + in.group[j]]) continue;
      bool overlap = true;
      for (int k = 0; k < in.dim; ++k)
        overlap &= !(in.hi[3 * i + k] < in.lo[3 * j + k] || in.hi[3 * j + k] < in.lo[3 * i + k]);
      if (overlap) out.emplace_back(static_cast<int>(i), static_cast<int>(j));
    }
  return out;
}

/// Polydisperse grains (radii 1 to 2.5 cm) in a 1 m box, long walls (a few 0.5–1 m boxes,
/// some tilted so their boxes are fat), one half-space, two groups, a few two-contactor bodies.
moreau::BroadPhaseInput scene(int dim, std::size_t grains, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  moreau::BroadPhaseInput in;
  in.dim = dim;
  in.groups = 2;
  in.interacts = {1, 1, 1, 0};  // grains with grains and with walls; walls never with walls
  auto add = [&](const double* lo, const double* hi, int body, int group) {
    for (int k = 0; k < 3; ++k) {
      in.lo.push_back(k < dim ? lo[k] : 0.0);
      in.hi.push_back(k < dim ? hi[k] : 0.0);
    }
    in.body.push_back(body);
    in.group.push_back(group);
  };
  int body = 0;
  for (std::size_t i = 0; i < grains; ++i) {
    const double r = 0.01 + 0.015 * u(rng);
    double c[3], lo[3], hi[3];
    for (int k = 0; k < 3; ++k) c[k] = u(rng), lo[k] = c[k] - r, hi[k] = c[k] + r;
    add(lo, hi, body, 0);
    if (i % 17 == 0) add(lo, hi, body, 0);  // a second contactor on the same body: never paired with the first
    ++body;
  }
  for (int w = 0; w < 5; ++w) {
    double lo[3], hi[3];
    for (int k = 0; k < 3; ++k) {
      const double a = u(rng), b = u(rng) * (w % 2 ? 1.0 : 0.02);  // thin or fat (tilted) boxes
      lo[k] = a - 0.5, hi[k] = a - 0.5 + (k == w % dim ? 1.0 : b + 0.01);
    }
    add(lo, hi, body++, 1);
  }
  const double inf = std::numeric_limits<double>::infinity();
  const double lo[3] = {-inf, -inf, -inf}, hi[3] = {inf, inf, inf};
  add(lo, hi, body++, 1);  // a half-space
  return in;
}

}  // namespace

TEST(GridBroadPhase, EqualsBruteForceWithLongWallsForAnyCell) {
  for (int dim : {2, 3})
    for (unsigned seed : {1u, 2u, 3u})
      for (const nlohmann::json& params : {nlohmann::json::object(), nlohmann::json{{"cell", 0.015}},
                                           nlohmann::json{{"cell", 0.3}}, nlohmann::json{{"large_ratio", 1e9}},
                                           nlohmann::json{{"large_ratio", 1.0}}}) {
        const auto in = scene(dim, dim == 2 ? 600 : 1500, seed);
        auto grid = moreau_test::create<moreau::BroadPhase>("grid", params, moreau::BuildContext{});
        Pairs got;
        grid->pairs(in, got);
        const Pairs expected = brute_force(in);
        EXPECT_TRUE(std::is_sorted(got.begin(), got.end()));
        EXPECT_EQ(got, expected) << dim << "D, seed " << seed << ", " << params.dump();
        grid->pairs(in, got);  // reused: the same again
        EXPECT_EQ(got, expected);
      }
}
