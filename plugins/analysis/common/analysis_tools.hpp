#pragma once
// What the analysis plugins share: axes and profiles in bins (parameters and binning),
// the sample's box, tensors as row-major d×d arrays, and which contacts a region holds.
#include <moreau/analysis.hpp>
#include <moreau/params.hpp>
#include <moreau/schema.hpp>
#include <string>
#include <vector>

namespace moreau::analysis {

/// An axis parameter: "x", "y", "z" or 0, 1, 2 (below the dimension).
int axis_of(const nlohmann::json& value, int dim, const std::string& pointer);

/// Bins along an axis (parameter object {"axis", "bins", "range"?}): `range` [from, to]
/// fixes them; without it they span the region's box in each frame.
struct Bins {
  bool on = false;
  int axis = 1;
  int count = 10;
  bool fixed_range = false;
  double from = 0, to = 0;
  std::string pointer;
  /// Parses `p`'s key (absent: bins off). `extra`: other keys the object may hold.
  static Bins parse(const Params& p, const std::string& key, int dim, const std::vector<std::string>& extra = {});
  /// The bin edges for a frame: the fixed range, or [lo, hi] of the region box.
  void edges(const double lo[3], const double hi[3], double& a, double& b) const;
  /// Bin of coordinate x in [a, b), or −1 outside.
  int bin(double x, double a, double b) const;
};

/// Centre of each of n bins over [a, b].
std::vector<double> bin_centres(int n, double a, double b);

/// Contacts whose point lies in the region (all of them for the whole sample).
std::vector<char> contacts_in(const AnalysisFrame& f, const Region& r);

/// Normal force of contact c (N, ≥ 0: impulse normal component / h).
inline double normal_force(const AnalysisFrame& f, std::size_t c) { return f.contacts.impulse[c * f.dimension] / f.h; }

/// Row-major d×d helpers.
using Tensor = std::vector<double>;
inline Tensor zeros(int d) { return Tensor(static_cast<std::size_t>(d * d), 0.0); }
/// t += s · a ⊗ b
inline void add_outer(Tensor& t, int d, double s, const double* a, const double* b) {
  for (int i = 0; i < d; ++i)
    for (int j = 0; j < d; ++j) t[i * d + j] += s * a[i] * b[j];
}

/// The schema key every analysis with a `profile` documents the same way.
void profile_param(Schema& s, const std::string& doc);

}  // namespace moreau::analysis
