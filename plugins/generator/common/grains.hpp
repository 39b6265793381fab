#pragma once
// The parts of a generated body the generator plugins share: the grain's shape (parameter
// `grain`), its size distribution (`size`), the keys every body gets (`body`) and its
// name, and the grid that keeps grains from overlapping.
#include <moreau/params.hpp>
#include <moreau/schema.hpp>
#include <nlohmann/json.hpp>
#include <string>
#include <unordered_map>
#include <vector>

#include "random.hpp"

namespace moreau::generate {

using nlohmann::json;

/// `grain`: {"shape": "disk" | "sphere" | "polygon" | "convex", "group": G, "sides": n
/// (polygon, regular), "corners": n (convex: random points on the circumscribed sphere)}.
/// Sizes are circumradii: the grain fits in the ball of that radius about its position.
struct GrainKind {
  std::string shape;
  std::string group = "grain";
  int sides = 6;
  int corners = 12;
  /// Parses key `key` of `p` for a scene of dimension `dim`.
  static GrainKind parse(const Params& p, const std::string& key, int dim);
  /// A contactor of circumradius r. Polygons turn by a random angle when `turn` is set;
  /// convex grains always draw their corners.
  json contactor(double r, Random& rng, bool turn) const;
};

/// `size`: a number (every grain that radius), or {"distribution": "uniform", "min", "max"},
/// {"distribution": "list", "values": [...], "fractions": [...]} (fractions of the number
/// of grains), {"distribution": "lognormal", "median", "sigma", "min"?, "max"?} (ln r normal
/// with mean ln median and standard deviation sigma, redrawn outside [min, max]).
struct SizeDistribution {
  std::string kind = "constant";
  double a = 0, b = 0;  // constant: a; uniform: [a, b]; lognormal: median a, sigma b
  double lo = 0, hi = 0;  // lognormal bounds (0 / inf: none)
  std::vector<double> values, fractions;
  std::string pointer;
  static SizeDistribution parse(const Params& p, const std::string& key);
  /// n radii, in grain order (a list is split exactly by its fractions, then shuffled).
  std::vector<double> draw(std::size_t n, Random& rng) const;
  double largest() const;
};

/// `body` (keys every generated body gets: material, velocity, fixed, model, …) and `name`
/// (bodies are named NAME_0, NAME_1, …, and must not clash with the scene's names).
struct BodyTemplate {
  json keys = json::object();
  std::string prefix = "grain";
  static BodyTemplate parse(const Params& p, const json& scene);
  json make(std::size_t index, const std::vector<double>& position, json contactor) const;
};

/// Circles (2D) or balls (3D) kept apart: a uniform grid of cells of side `cell` ≥ the
/// largest diameter stored, so a query looks at the neighbouring cells only.
class BallGrid {
 public:
  BallGrid(int dim, double cell) : dim_(dim), cell_(cell) {}
  void add(const double* x, double r);
  /// Smallest gap between ball (x, r) and the stored balls (+inf if none is near).
  double gap(const double* x, double r) const;
  std::size_t size() const { return r_.size(); }

 private:
  long long key(const long long c[3]) const { return (c[0] * 73856093LL) ^ (c[1] * 19349663LL) ^ (c[2] * 83492791LL); }
  void cell_of(const double* x, long long c[3]) const;
  int dim_;
  double cell_;
  std::vector<double> x_, r_;
  std::unordered_map<long long, std::vector<std::size_t>> cells_;
};

/// Shared schema keys.
void grain_params(Schema& s);

}  // namespace moreau::generate
