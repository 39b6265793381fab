// `grid`: a uniform grid broad phase. Each box goes into the cell of its lower corner,
// with cells at least as large as the largest box, so two overlapping boxes sit in the
// same or neighbouring cells: the cost is linear in the number of contactors.
// Boxes far larger than the typical one (walls, floors: more than `large_ratio` times the
// median box) would make every cell huge and the cost quadratic, so they are kept out of
// the cell size and tested against the boxes of every cell they overlap (or against all
// boxes, if that is fewer). Unbounded shapes (half-spaces) are tested against every
// contactor.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <moreau/broadphase.hpp>

namespace {
using namespace moreau;

class Grid : public BroadPhase {
 public:
  static Schema schema() {
    Schema s;
    s.number("cell", "cell size (0: the largest box among those at most large_ratio times the median box; "
                     "boxes larger than the cell are tested against the cells they overlap)")
        .units("m").min(0).fallback(0.0);
    s.number("large_ratio", "with cell 0: boxes larger than this many times the median box (walls, floors) are "
                            "kept out of the cell size").min(1).fallback(4.0);
    return s;
  }
  static constexpr const char* doc = "uniform grid broad phase (linear cost)";
  Grid(const Params& p, const BuildContext&)
      : cell_(p.has("cell") ? p.number("cell") : 0.0), large_ratio_(p.has("large_ratio") ? p.number("large_ratio") : 4.0) {}

  void pairs(const BroadPhaseInput& in, std::vector<std::pair<int, int>>& out) override {
    out.clear();
    const std::size_t n = in.body.size();
    const int d = in.dim;
    std::vector<int> bounded, unbounded, large;
    extent_of_.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      bool finite = true;
      double e = 0;
      for (int k = 0; k < d; ++k) {
        finite &= std::isfinite(in.lo[3 * i + k]) && std::isfinite(in.hi[3 * i + k]);
        e = std::max(e, in.hi[3 * i + k] - in.lo[3 * i + k]);
      }
      extent_of_[i] = e;
      (finite ? bounded : unbounded).push_back(static_cast<int>(i));
    }
    const double size = split_large(bounded, large);
    auto ok = [&](int i, int j) {
      if (in.body[i] == in.body[j]) return false;
      if (!in.interacts[in.group[i] * in.groups + in.group[j]]) return false;
      for (int k = 0; k < d; ++k)
        if (in.hi[3 * i + k] < in.lo[3 * j + k] || in.hi[3 * j + k] < in.lo[3 * i + k]) return false;
      return true;
    };
    auto push = [&](int i, int j) { out.emplace_back(std::min(i, j), std::max(i, j)); };
    packed_.clear();
    if (size > 0 && !bounded.empty()) {
      // Cells are hashed into a table of 2^k ≥ 2n buckets, filled by a counting sort into
      // one packed array (cell, box, body, group of each contactor, bucket after bucket):
      // linear time, and the neighbour scans read contiguous memory instead of chasing
      // contactor indices through the input arrays.
      const double inv = 1 / size;
      inv_ = inv;
      // Dense cell numbering (x fastest) when the occupied region has at most 8 cells per
      // contactor: cells near in space are near in memory, so the scans stay in cache.
      // Otherwise (scattered contactors) cells are hashed into 2^k ≥ 2n buckets.
      std::int64_t cmin[3] = {0, 0, 0}, cmax[3] = {0, 0, 0};
      for (int k = 0; k < d; ++k) {
        cmin[k] = INT64_MAX;
        cmax[k] = INT64_MIN;
      }
      cell_of_.resize(n);
      for (int i : bounded) {
        for (int k = 0; k < d; ++k) {
          const auto c = static_cast<std::int64_t>(std::floor(in.lo[3 * i + k] * inv));
          cell_of_[i][k] = c;
          cmin[k] = std::min(cmin[k], c);
          cmax[k] = std::max(cmax[k], c);
        }
        if (d == 2) cell_of_[i][2] = 0;
      }
      for (int k = 0; k < 3; ++k) {
        block_lo_[k] = k < d ? cmin[k] : 0;
        block_hi_[k] = k < d ? cmax[k] : 0;
      }
      double dense_cells = 1;
      for (int k = 0; k < d; ++k) dense_cells *= static_cast<double>(cmax[k] - cmin[k] + 3);
      dense_ = dense_cells <= 8.0 * static_cast<double>(bounded.size()) + 64;
      for (int k = 0; k < 3; ++k) {
        origin_[k] = k < d ? cmin[k] - 1 : 0;
        extent_[k] = k < d ? cmax[k] - cmin[k] + 3 : 1;
      }
      std::size_t buckets = 1;
      if (dense_) {
        buckets = static_cast<std::size_t>(dense_cells);
      } else {
        while (buckets < 2 * bounded.size()) buckets <<= 1;
      }
      mask_ = buckets - 1;
      start_.assign(buckets + 1, 0);
      for (int i : bounded) ++start_[bucket(cell_of_[i][0], cell_of_[i][1], cell_of_[i][2]) + 1];
      for (std::size_t k = 0; k < buckets; ++k) start_[k + 1] += start_[k];
      fill_.assign(start_.begin(), start_.end() - 1);
      packed_.resize(bounded.size());
      for (int i : bounded) {
        const auto& c = cell_of_[i];
        Item& it = packed_[fill_[bucket(c[0], c[1], c[2])]++];
        it.cell = c;
        it.index = i;
        it.body = in.body[i];
        it.group = in.group[i];
        for (int k = 0; k < 3; ++k) it.lo[k] = in.lo[3 * i + k], it.hi[k] = in.hi[3 * i + k];
      }
      const int zr = d == 3 ? 1 : 0;
      for (const Item& a : packed_) {
        for (int dx = -1; dx <= 1; ++dx)
          for (int dy = -1; dy <= 1; ++dy)
            for (int dz = -zr; dz <= zr; ++dz) {
              const std::int64_t nc[3] = {a.cell[0] + dx, a.cell[1] + dy, a.cell[2] + dz};
              const std::uint64_t h = bucket(nc[0], nc[1], nc[2]);
              for (std::size_t m = start_[h]; m < start_[h + 1]; ++m) {
                const Item& b = packed_[m];
                if (b.index <= a.index) continue;
                // Another cell may share the bucket: only the true neighbour counts.
                if (b.cell[0] != nc[0] || b.cell[1] != nc[1] || b.cell[2] != nc[2]) continue;
                if (a.body == b.body || !in.interacts[a.group * in.groups + b.group]) continue;
                bool overlap = true;
                for (int k = 0; k < d; ++k) overlap &= !(a.hi[k] < b.lo[k] || b.hi[k] < a.lo[k]);
                if (overlap) out.emplace_back(a.index, b.index);
              }
            }
      }
    }
    for (int u : unbounded)
      for (std::size_t j = 0; j < n; ++j)
        if (static_cast<int>(j) != u && (std::find(unbounded.begin(), unbounded.end(), static_cast<int>(j)) == unbounded.end() || u < static_cast<int>(j)) &&
            ok(u, static_cast<int>(j)))
          push(u, static_cast<int>(j));
    large_pairs(in, large, out);
    sort_pairs(n, out);
  }

 private:
  /// The cell size; moves the boxes larger than it from `bounded` to `large`. A given
  /// `cell` is the size; with 0 it is the largest box among those at most `large_ratio`
  /// times the median box.
  double split_large(std::vector<int>& bounded, std::vector<int>& large) {
    if (bounded.empty()) return cell_;
    double size = cell_;
    if (size == 0) {
      sizes_.clear();
      for (int i : bounded) sizes_.push_back(extent_of_[i]);
      auto mid = sizes_.begin() + static_cast<std::ptrdiff_t>(sizes_.size() / 2);
      std::nth_element(sizes_.begin(), mid, sizes_.end());
      const double limit = large_ratio_ * *mid;
      for (int i : bounded)
        if (extent_of_[i] <= limit) size = std::max(size, extent_of_[i]);
    }
    std::size_t kept = 0;
    for (int i : bounded) {
      if (extent_of_[i] > size) large.push_back(i);
      else bounded[kept++] = i;
    }
    bounded.resize(kept);
    return size;
  }

  /// Pairs of a large box: with the grid's boxes in every cell it overlaps (a box belongs
  /// to the cell of its lower corner, so the scan starts a cell lower), or with every
  /// grid box if that is fewer to test; then large boxes with each other.
  void large_pairs(const BroadPhaseInput& in, const std::vector<int>& large, std::vector<std::pair<int, int>>& out) {
    if (large.empty()) return;
    const int d = in.dim;
    auto overlap = [&](const double* lo, const double* hi, const Item& b) {
      for (int k = 0; k < d; ++k)
        if (hi[k] < b.lo[k] || b.hi[k] < lo[k]) return false;
      return true;
    };
    for (int L : large) {
      const double* lo = &in.lo[3 * L];
      const double* hi = &in.hi[3 * L];
      const int body = in.body[L], group = in.group[L];
      auto consider = [&](const Item& b) {
        if (b.body == body || !in.interacts[group * in.groups + b.group] || !overlap(lo, hi, b)) return;
        out.emplace_back(std::min(L, b.index), std::max(L, b.index));
      };
      if (!packed_.empty()) {
        // The cells the box overlaps, within the block that holds grid boxes.
        std::int64_t from[3] = {0, 0, 0}, to[3] = {0, 0, 0};
        double cells = 1;
        for (int k = 0; k < d; ++k) {
          from[k] = std::max(static_cast<std::int64_t>(std::floor(lo[k] * inv_)) - 1, block_lo_[k]);
          to[k] = std::min(static_cast<std::int64_t>(std::floor(hi[k] * inv_)), block_hi_[k]);
          cells *= static_cast<double>(std::max<std::int64_t>(0, to[k] - from[k] + 1));
        }
        if (cells <= static_cast<double>(packed_.size())) {
          for (std::int64_t z = from[2]; z <= to[2]; ++z)
            for (std::int64_t y = from[1]; y <= to[1]; ++y)
              for (std::int64_t x = from[0]; x <= to[0]; ++x) {
                const std::uint64_t h = bucket(x, y, z);
                for (std::size_t m = start_[h]; m < start_[h + 1]; ++m) {
                  const Item& b = packed_[m];
                  if (b.cell[0] == x && b.cell[1] == y && b.cell[2] == z) consider(b);
                }
              }
        } else {
          for (const Item& b : packed_) consider(b);
        }
      }
      for (int M : large) {
        if (M <= L || in.body[M] == body || !in.interacts[group * in.groups + in.group[M]]) continue;
        bool touch = true;
        for (int k = 0; k < d; ++k) touch &= !(hi[k] < in.lo[3 * M + k] || in.hi[3 * M + k] < lo[k]);
        if (touch) out.emplace_back(L, M);
      }
    }
  }

  /// Sorts the pairs by (first, second) in linear time: a counting sort on the first index,
  /// then each first's few partners sorted in place (a comparison sort of all pairs was the
  /// one super-linear step). Every pair is found once (one cell per box, each neighbour
  /// cell scanned once; half-spaces once per partner), so there is nothing to deduplicate.
  /// The order is what the narrow phase and the solver's contact order follow.
  void sort_pairs(std::size_t n, std::vector<std::pair<int, int>>& out) {
    first_.assign(n + 1, 0);
    for (const auto& p : out) ++first_[static_cast<std::size_t>(p.first) + 1];
    for (std::size_t i = 0; i < n; ++i) first_[i + 1] += first_[i];
    sorted_.resize(out.size());
    fill_.assign(first_.begin(), first_.end() - 1);
    for (const auto& p : out) sorted_[fill_[static_cast<std::size_t>(p.first)]++] = p;
    for (std::size_t i = 0; i < n; ++i)
      std::sort(sorted_.begin() + static_cast<std::ptrdiff_t>(first_[i]), sorted_.begin() + static_cast<std::ptrdiff_t>(first_[i + 1]));
    out.swap(sorted_);
  }
  /// The bucket of a cell. Dense: cells outside the numbered block (only neighbours of
  /// border cells, which the block's one-cell margin already covers) go to bucket 0, the
  /// margin's corner, which holds no contactor.
  std::uint64_t bucket(std::int64_t x, std::int64_t y, std::int64_t z) const {
    if (!dense_) return hash(x, y, z) & mask_;
    const std::int64_t a = x - origin_[0], b = y - origin_[1], c = z - origin_[2];
    if (a < 0 || b < 0 || c < 0 || a >= extent_[0] || b >= extent_[1] || c >= extent_[2]) return 0;
    return static_cast<std::uint64_t>(a + extent_[0] * (b + extent_[1] * c));
  }
  static std::uint64_t hash(std::int64_t x, std::int64_t y, std::int64_t z) {
    return static_cast<std::uint64_t>(x) * 73856093ULL ^ static_cast<std::uint64_t>(y) * 19349663ULL ^
           static_cast<std::uint64_t>(z) * 83492791ULL;
  }
  double cell_, large_ratio_;
  std::vector<double> extent_of_, sizes_;  // per contactor: largest side of its box; scratch for the median
  double inv_ = 0;                          // 1 / cell size of the last grid
  std::int64_t block_lo_[3] = {0, 0, 0}, block_hi_[3] = {0, 0, 0};  // cells that hold grid boxes
  struct Item {
    std::array<std::int64_t, 3> cell;
    int index, body, group;
    double lo[3], hi[3];
  };
  std::vector<std::array<std::int64_t, 3>> cell_of_;
  bool dense_ = false;
  std::int64_t origin_[3] = {0, 0, 0}, extent_[3] = {1, 1, 1};
  std::uint64_t mask_ = 0;
  std::vector<std::size_t> start_, fill_;  // bucket b holds packed_[start_[b] .. start_[b+1])
  std::vector<Item> packed_;
  std::vector<std::size_t> first_;  // sort_pairs: pairs of first index i at [first_[i], first_[i+1])
  std::vector<std::pair<int, int>> sorted_;
};
MOREAU_REGISTER(Grid, "grid")
}  // namespace
MOREAU_PLUGIN_LIBRARY("moreau_broadphase_grid")
