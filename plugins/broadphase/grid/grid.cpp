// `grid`: a uniform grid broad phase. Each bounded box goes into the cell of its lower
// corner, with cells at least as large as the largest box, so two overlapping boxes sit
// in the same or neighbouring cells: the cost is linear in the number of contactors.
// Unbounded shapes (half-spaces) are tested against every contactor.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <moreau/broadphase.hpp>
#include <unordered_map>

namespace {
using namespace moreau;

class Grid : public BroadPhase {
 public:
  static Schema schema() {
    Schema s;
    s.number("cell", "cell size (0: the largest bounding box)").units("m").min(0).fallback(0.0);
    return s;
  }
  static constexpr const char* doc = "uniform grid broad phase (linear cost)";
  Grid(const Params& p, const BuildContext&) : cell_(p.has("cell") ? p.number("cell") : 0.0) {}

  void pairs(const BroadPhaseInput& in, std::vector<std::pair<int, int>>& out) override {
    out.clear();
    const std::size_t n = in.body.size();
    const int d = in.dim;
    std::vector<int> bounded, unbounded;
    double size = cell_;
    for (std::size_t i = 0; i < n; ++i) {
      bool finite = true;
      for (int k = 0; k < d; ++k) finite &= std::isfinite(in.lo[3 * i + k]) && std::isfinite(in.hi[3 * i + k]);
      (finite ? bounded : unbounded).push_back(static_cast<int>(i));
      if (finite && cell_ == 0)
        for (int k = 0; k < d; ++k) size = std::max(size, in.hi[3 * i + k] - in.lo[3 * i + k]);
    }
    auto ok = [&](int i, int j) {
      if (in.body[i] == in.body[j]) return false;
      if (!in.interacts[in.group[i] * in.groups + in.group[j]]) return false;
      for (int k = 0; k < d; ++k)
        if (in.hi[3 * i + k] < in.lo[3 * j + k] || in.hi[3 * j + k] < in.lo[3 * i + k]) return false;
      return true;
    };
    auto push = [&](int i, int j) { out.emplace_back(std::min(i, j), std::max(i, j)); };
    if (size > 0 && !bounded.empty()) {
      const double inv = 1 / size;
      cells_.clear();
      keys_.resize(n);
      for (int i : bounded) {
        std::int64_t c[3] = {0, 0, 0};
        for (int k = 0; k < d; ++k) c[k] = static_cast<std::int64_t>(std::floor(in.lo[3 * i + k] * inv));
        keys_[i] = {c[0], c[1], c[2]};
        cells_[hash(c[0], c[1], c[2])].push_back(i);
      }
      for (int i : bounded) {
        const auto& c = keys_[i];
        const int zr = d == 3 ? 1 : 0;
        for (int dx = -1; dx <= 1; ++dx)
          for (int dy = -1; dy <= 1; ++dy)
            for (int dz = -zr; dz <= zr; ++dz) {
              auto it = cells_.find(hash(c[0] + dx, c[1] + dy, c[2] + dz));
              if (it == cells_.end()) continue;
              for (int j : it->second) {
                if (j <= i) continue;
                const auto& cj = keys_[j];  // hash collisions: check the cell really is a neighbour
                if (std::abs(cj[0] - c[0]) > 1 || std::abs(cj[1] - c[1]) > 1 || std::abs(cj[2] - c[2]) > 1) continue;
                if (ok(i, j)) push(i, j);
              }
            }
      }
    }
    for (int u : unbounded)
      for (std::size_t j = 0; j < n; ++j)
        if (static_cast<int>(j) != u && (std::find(unbounded.begin(), unbounded.end(), static_cast<int>(j)) == unbounded.end() || u < static_cast<int>(j)) &&
            ok(u, static_cast<int>(j)))
          push(u, static_cast<int>(j));
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
  }

 private:
  static std::uint64_t hash(std::int64_t x, std::int64_t y, std::int64_t z) {
    return static_cast<std::uint64_t>(x) * 73856093ULL ^ static_cast<std::uint64_t>(y) * 19349663ULL ^
           static_cast<std::uint64_t>(z) * 83492791ULL;
  }
  double cell_;
  std::unordered_map<std::uint64_t, std::vector<int>> cells_;
  std::vector<std::array<std::int64_t, 3>> keys_;
};
MOREAU_REGISTER(Grid, "grid")
}  // namespace
MOREAU_PLUGIN_LIBRARY("moreau_broadphase_grid")
