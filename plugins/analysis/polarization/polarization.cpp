// `polarization`: where the contact forces of a region lie in their Coulomb cones, per pair
// of contactor groups (grain–grain, grain–wall, …; Dumont, Fortin & Ouafik 2010). A contact
// is open (r_n = 0), sticking (strictly inside the cone), or sliding: on the cone's
// boundary, ‖r_t‖ ≥ (1 − tol) μ r_n — the "polarized" contacts of the paper, whether or not
// they move in this step (those that do, with a tangential velocity, are also counted as
// `moving`, the output's status 2). The mobilisation ‖r_t‖/(μ r_n) of the closed contacts
// is given as a histogram over [0, 1].
#include <analysis_tools.hpp>
#include <cmath>
#include <moreau/analysis.hpp>
#include <moreau/error.hpp>

namespace {

using namespace moreau;
using namespace moreau::analysis;

class Polarization : public Analysis {
 public:
  static Schema schema() {
    Schema s;
    s.array("pairs", "the group pairs reported, [[g1, g2], ...] (default: the scene's interactions)").optional();
    s.integer("bins", "bins of the mobilisation histogram over [0, 1]").min(1).max(10000).fallback(10);
    s.number("cone_tolerance", "a closed contact is on the cone's boundary when |r_t| >= (1 - tol) mu r_n")
        .min(0)
        .lt(1)
        .fallback(1e-3);
    return s;
  }
  static constexpr const char* doc =
      "shares of contacts open, sticking and sliding (on the Coulomb cone) per group pair, mobilisation histogram";

  Polarization(const Params& p, const BuildContext&)
      : bins_(static_cast<int>(p.integer("bins"))), tol_(p.number("cone_tolerance")) {
    if (p.has("pairs")) pairs_json_ = p.raw("pairs"), pairs_pointer_ = p.pointer("pairs");
  }

  void prepare(const AnalysisSetup& s) override {
    if (pairs_pointer_.empty()) {
      for (const auto& in : s.interactions) add_pair(in[0], in[1]);
      return;
    }
    for (std::size_t i = 0; i < pairs_json_.size(); ++i) {
      const auto& pr = pairs_json_[i];
      const std::string ptr = pairs_pointer_ + "/" + std::to_string(i);
      if (!pr.is_array() || pr.size() != 2 || !pr[0].is_string() || !pr[1].is_string())
        throw InputError(ptr, "expected a pair of group names [g1, g2], got " + pr.dump());
      for (int k = 0; k < 2; ++k) {
        const std::string g = pr[k].get<std::string>();
        bool known = false;
        for (const auto& x : s.groups) known = known || x == g;
        if (!known) {
          std::string list;
          for (const auto& x : s.groups) list += (list.empty() ? "" : ", ") + x;
          throw InputError(ptr + "/" + std::to_string(k), "no contactor has group \"" + g + "\" (groups: " + list + ")");
        }
      }
      add_pair(pr[0].get<std::string>(), pr[1].get<std::string>());
    }
  }

  void run(const AnalysisFrame& f, const Region& region, AnalysisResult& out) override {
    const std::size_t np = pairs_.size(), nb = static_cast<std::size_t>(bins_);
    // Group indices of each pair in this frame's numbering (−1: a group that never touches).
    std::vector<std::array<int, 2>> idx(np, {-1, -1});
    for (std::size_t p = 0; p < np; ++p)
      for (int k = 0; k < 2; ++k)
        for (std::size_t g = 0; g < f.group_names.size(); ++g)
          if (f.group_names[g] == pairs_[p][static_cast<std::size_t>(k)]) idx[p][static_cast<std::size_t>(k)] = static_cast<int>(g);
    enum { open, sticking, sliding, moving, total, columns };
    std::vector<double> counts(np * columns, 0.0), hist(np * nb, 0.0), mean(np, 0.0);
    const auto in = contacts_in(f, region);
    for (std::size_t c = 0; c < f.contacts.count; ++c) {
      if (!in[c]) continue;
      const int ga = f.contacts.groups[2 * c], gb = f.contacts.groups[2 * c + 1];
      for (std::size_t p = 0; p < np; ++p) {
        if (!((ga == idx[p][0] && gb == idx[p][1]) || (ga == idx[p][1] && gb == idx[p][0]))) continue;
        double* row = &counts[p * columns];
        row[total] += 1;
        if (!(f.contacts.impulse[c * f.dimension] > 0)) {
          row[open] += 1;
          continue;
        }
        const double m = mobilisation(f, c);
        row[m >= 1 - tol_ ? sliding : sticking] += 1;
        if (f.contacts.status[c] == 2) row[moving] += 1;
        mean[p] += m;
        const int k = std::min(bins_ - 1, static_cast<int>(std::min(m, 1.0) * bins_));
        hist[p * nb + static_cast<std::size_t>(k)] += 1;
      }
    }
    std::vector<double> shares(np * 3, 0.0);
    std::vector<std::string> names;
    for (std::size_t p = 0; p < np; ++p) {
      const double* row = &counts[p * columns];
      const double closed = row[total] - row[open];
      if (closed > 0) mean[p] /= closed;
      for (int k = 0; k < 3; ++k) shares[p * 3 + static_cast<std::size_t>(k)] = row[total] > 0 ? row[k] / row[total] : 0.0;
      names.push_back(pairs_[p][0] + "-" + pairs_[p][1]);
    }
    std::vector<double> edges(nb + 1);
    for (std::size_t k = 0; k <= nb; ++k) edges[k] = static_cast<double>(k) / static_cast<double>(nb);
    out.strings("pairs", names);
    out.strings("columns", {"open", "sticking", "sliding", "moving", "total"});
    out.add("counts", {np, static_cast<std::size_t>(columns)}, counts);
    out.add("shares", {np, 3}, shares);
    out.add("mobilisation_mean", {np}, mean);
    out.add("mobilisation_histogram", {np, nb}, hist);
    out.add("mobilisation_edges", {nb + 1}, edges);
  }

 private:
  void add_pair(const std::string& a, const std::string& b) {
    for (const auto& p : pairs_)
      if ((p[0] == a && p[1] == b) || (p[0] == b && p[1] == a)) return;
    pairs_.push_back({a, b});
  }

  int bins_;
  double tol_;
  nlohmann::json pairs_json_;
  std::string pairs_pointer_;
  std::vector<std::array<std::string, 2>> pairs_;
};

MOREAU_REGISTER(Polarization, "polarization")

}  // namespace

MOREAU_PLUGIN_LIBRARY("moreau_analysis_polarization")
