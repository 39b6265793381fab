// `fabric`: the contact network of a region. Over the sample bodies whose centre lies in
// the region and the force-carrying contacts (r_n > 0) they take part in:
//  - coordination z = Σ_p n_p / N (n_p: force-carrying contacts of body p, walls included),
//    and z* without rattlers: bodies with fewer than `rattler_contacts` (default d) such
//    contacts, removed repeatedly (removing one can make a neighbour a rattler);
//  - solid (packing) fraction Σ_p V_p / V, V the region's box;
//  - fabric tensor F = ⟨n ⊗ n⟩ (trace 1);
//  - normal forces: mean ⟨f_n⟩, pdf of f_n/⟨f_n⟩ (normalised: Σ pdf·width = the share of
//    contacts within the range), strong network f_n > ⟨f_n⟩: its share of the contacts
//    and of Σ f_n.
#include <analysis_tools.hpp>
#include <cmath>
#include <moreau/analysis.hpp>

namespace {

using namespace moreau;
using namespace moreau::analysis;

class Fabric : public Analysis {
 public:
  static Schema schema() {
    Schema s;
    s.integer("bins", "bins of the normal-force pdf").min(1).max(100000).fallback(20);
    s.number("pdf_max", "upper end of the pdf's range of f_n / <f_n>").gt(0).fallback(4.0);
    s.integer("rattler_contacts", "bodies with fewer force-carrying contacts are rattlers (default: the dimension)")
        .min(1)
        .optional();
    return s;
  }
  static constexpr const char* doc =
      "coordination (with and without rattlers), solid fraction, fabric tensor, normal-force pdf, strong network";

  Fabric(const Params& p, const BuildContext& ctx)
      : bins_(static_cast<int>(p.integer("bins"))),
        pdf_max_(p.number("pdf_max")),
        rattler_(p.has("rattler_contacts") ? static_cast<int>(p.integer("rattler_contacts")) : ctx.dimension) {}

  void run(const AnalysisFrame& f, const Region& region, AnalysisResult& out) override {
    const int d = f.dimension;
    const std::size_t nb = f.bodies.count, nc = f.contacts.count;
    const auto in = bodies_in(f, region);
    // The force-carrying contacts of the region's bodies.
    std::vector<std::size_t> active;
    for (std::size_t c = 0; c < nc; ++c) {
      if (!(f.contacts.impulse[c * d] > 0)) continue;
      if (in[static_cast<std::size_t>(f.contacts.bodies[2 * c])] || in[static_cast<std::size_t>(f.contacts.bodies[2 * c + 1])])
        active.push_back(c);
    }
    std::vector<int> n(nb, 0);
    for (std::size_t c : active)
      for (int s = 0; s < 2; ++s) ++n[static_cast<std::size_t>(f.contacts.bodies[2 * c + s])];
    double bodies = 0, links = 0, solid = 0;
    for (std::size_t b = 0; b < nb; ++b)
      if (in[b]) bodies += 1, links += n[b], solid += f.bodies.volume[b];
    // Rattlers, removed until none is left: a removed body's contacts no longer count.
    std::vector<std::vector<std::size_t>> partners(nb);
    for (std::size_t c : active) {
      const std::size_t x = static_cast<std::size_t>(f.contacts.bodies[2 * c]);
      const std::size_t y = static_cast<std::size_t>(f.contacts.bodies[2 * c + 1]);
      partners[x].push_back(y);
      partners[y].push_back(x);
    }
    std::vector<char> kept(nb, 1);
    std::vector<int> m = n;
    std::vector<std::size_t> queue;
    for (std::size_t b = 0; b < nb; ++b)
      if (in[b] && m[b] < rattler_) kept[b] = 0, queue.push_back(b);
    while (!queue.empty()) {
      const std::size_t b = queue.back();
      queue.pop_back();
      for (std::size_t y : partners[b]) {
        if (!kept[y]) continue;
        if (--m[y] < rattler_ && in[y]) kept[y] = 0, queue.push_back(y);
      }
    }
    double firm = 0, firm_links = 0;
    for (std::size_t b = 0; b < nb; ++b)
      if (in[b] && kept[b]) firm += 1, firm_links += m[b];

    Tensor F = zeros(d);
    double sum_f = 0;
    for (std::size_t c : active) {
      const double* nrm = &f.contacts.frame[c * d * d];  // row 0: the normal
      add_outer(F, d, 1.0, nrm, nrm);
      sum_f += normal_force(f, c);
    }
    const double na = static_cast<double>(active.size());
    for (double& x : F) x = na > 0 ? x / na : 0.0;
    const double mean = na > 0 ? sum_f / na : 0.0;
    std::vector<double> pdf(static_cast<std::size_t>(bins_), 0.0), edges(static_cast<std::size_t>(bins_) + 1);
    const double width = pdf_max_ / bins_;
    for (int k = 0; k <= bins_; ++k) edges[static_cast<std::size_t>(k)] = k * width;
    double strong = 0, strong_f = 0, beyond = 0;
    for (std::size_t c : active) {
      const double x = normal_force(f, c) / mean;
      if (x > 1) strong += 1, strong_f += normal_force(f, c);
      const int k = static_cast<int>(x / width);
      if (k < bins_) pdf[static_cast<std::size_t>(k)] += 1 / (na * width);
      else beyond += 1;
    }
    double lo[3], hi[3];
    const bool any = region_box(f, region, lo, hi);
    const double V = any ? box_volume(lo, hi, d) : 0.0;
    const std::size_t ds = static_cast<std::size_t>(d), nbins = static_cast<std::size_t>(bins_);
    out.scalar("bodies", bodies);
    out.scalar("contacts", na);
    out.scalar("coordination", bodies > 0 ? links / bodies : 0.0);
    out.scalar("coordination_no_rattlers", firm > 0 ? firm_links / firm : 0.0);
    out.scalar("rattler_fraction", bodies > 0 ? (bodies - firm) / bodies : 0.0);
    out.scalar("solid_fraction", V > 0 ? solid / V : 0.0);
    out.scalar("volume", V, d == 2 ? "m2" : "m3");
    out.add("fabric", {ds, ds}, F);
    out.scalar("mean_normal_force", mean, d == 2 ? "N/m" : "N");
    out.add("pdf", {nbins}, pdf);
    out.add("pdf_edges", {nbins + 1}, edges);
    out.scalar("pdf_beyond", na > 0 ? beyond / na : 0.0);
    out.scalar("strong_share", na > 0 ? strong / na : 0.0);
    out.scalar("strong_force_share", sum_f > 0 ? strong_f / sum_f : 0.0);
  }

 private:
  int bins_;
  double pdf_max_;
  int rattler_;
};

MOREAU_REGISTER(Fabric, "fabric")

}  // namespace

MOREAU_PLUGIN_LIBRARY("moreau_analysis_fabric")
