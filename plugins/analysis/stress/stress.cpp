// `stress`: the mean stress tensor of a region, valid in statics and in dynamics
// (de Saxcé, Fortin & Millet 2004; eq. 16 of Dumont, Fortin & Ouafik 2010):
//
//   Σ = (1/V) Σ_p [ Σ_{c∈p} x_c ⊗ r_c + ∫_p x ⊗ ρ(g − ẍ) dV ] = Σ_r + Σ_g + Σ_γ (+ Σ_f)
//
// over the sample bodies p whose centre lies in the region (fixed and driven bodies are
// the boundary). For a rigid body, ∫ x ⊗ ρ g dV = m x_G ⊗ g and
// ∫ x ⊗ ρ ẍ dV = m x_G ⊗ a_G + J W² − J A (J = ∫ρ y⊗y dV about the centre, W = [ω]×,
// A = [α]×). A contact between two bodies of the region adds x_c ⊗ r − x_c ⊗ r = 0: only
// the contacts with bodies outside it (walls, the rest of the packing) count in Σ_r.
// Discretely, over the frame's step: r = impulse / h, a = (v⁺ − v⁻)/h, α = (ω⁺ − ω⁻)/h,
// ω in W at the mid-step, and x_G at the detection configuration (the point the impulses'
// lever arms start from), so that the momentum balances of the θ-scheme make Σ symmetric
// and independent of the origin to rounding (3D bodies with non-isotropic inertia: to the
// O(h) of the integrator's gyroscopic term). Each term depends on the origin; their sum
// does not. A deformable body will add its own ∫ terms (its nodes as point masses).
#include <analysis_tools.hpp>
#include <cmath>
#include <moreau/analysis.hpp>

namespace {

using namespace moreau;
using namespace moreau::analysis;

struct Terms {
  Tensor contact, gravity, inertia, external;
  double mass = 0, volume_solid = 0;
  std::vector<double> momentum;
  long bodies = 0;
  explicit Terms(int d) : contact(zeros(d)), gravity(zeros(d)), inertia(zeros(d)), external(zeros(d)), momentum(d, 0.0) {}
};

/// The terms of Σ·V for the bodies `in`, moments about `o`.
Terms terms(const AnalysisFrame& f, const std::vector<char>& in, const double* o) {
  const int d = f.dimension, r = d == 2 ? 1 : 3;
  const auto& B = f.bodies;
  Terms t(d);
  // Σ_r: contacts with one side in the region.
  for (std::size_t c = 0; c < f.contacts.count; ++c) {
    const int b0 = f.contacts.bodies[2 * c], b1 = f.contacts.bodies[2 * c + 1];
    const bool in0 = in[static_cast<std::size_t>(b0)], in1 = in[static_cast<std::size_t>(b1)];
    if (in0 == in1) continue;  // outside, or inside on both sides: x_c ⊗ r − x_c ⊗ r
    double force[3];
    contact_force(f, c, force);
    double x[3] = {0, 0, 0};
    for (int k = 0; k < d; ++k) x[k] = f.contacts.point[c * d + k] - o[k];
    add_outer(t.contact, d, in0 ? 1.0 : -1.0, x, force);
  }
  const double* g = f.gravity.data();
  for (std::size_t b = 0; b < B.count; ++b) {
    if (!in[b]) continue;
    ++t.bodies;
    const double m = B.mass[b];
    t.mass += m;
    t.volume_solid += B.volume[b];
    double x[3] = {0, 0, 0}, a[3] = {0, 0, 0};
    for (int k = 0; k < d; ++k) {
      x[k] = B.lever_position[b * d + k] - o[k];
      a[k] = (B.velocity_end[b * d + k] - B.velocity_begin[b * d + k]) / f.h;
      t.momentum[static_cast<std::size_t>(k)] += m * B.velocity_end[b * d + k];
    }
    add_outer(t.gravity, d, m, x, g);
    add_outer(t.external, d, 1.0, x, &B.force[b * d]);
    add_outer(t.inertia, d, -m, x, a);
    // Rotation: −(J W² − J A), and a torque's couple −½[τ]× in the external term.
    double w[3] = {0, 0, 0}, al[3] = {0, 0, 0}, tau[3] = {0, 0, 0};
    for (int k = 0; k < r; ++k) {
      const int kk = r == 1 ? 2 : k;  // 2D: the rotation is about z
      w[kk] = 0.5 * (B.angular_velocity_begin[b * r + k] + B.angular_velocity_end[b * r + k]);
      al[kk] = (B.angular_velocity_end[b * r + k] - B.angular_velocity_begin[b * r + k]) / f.h;
      tau[kk] = B.torque[b * r + k];
    }
    const double W[9] = {0, -w[2], w[1], w[2], 0, -w[0], -w[1], w[0], 0};
    const double A[9] = {0, -al[2], al[1], al[2], 0, -al[0], -al[1], al[0], 0};
    const double T[9] = {0, -tau[2], tau[1], tau[2], 0, -tau[0], -tau[1], tau[0], 0};
    double W2[9];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        double s = 0;
        for (int k = 0; k < 3; ++k) s += W[3 * i + k] * W[3 * k + j];
        W2[3 * i + j] = s;
      }
    const double* J = &B.second_moment[b * d * d];
    for (int i = 0; i < d; ++i)
      for (int j = 0; j < d; ++j) {
        double s = 0;
        for (int k = 0; k < d; ++k) s += J[i * d + k] * (W2[3 * k + j] - A[3 * k + j]);
        t.inertia[static_cast<std::size_t>(i * d + j)] -= s;
        t.external[static_cast<std::size_t>(i * d + j)] -= 0.5 * T[3 * i + j];
      }
  }
  return t;
}

class Stress : public Analysis {
 public:
  static Schema schema() {
    Schema s;
    s.vector("origin", "point about which the moments of each term are taken (the total does not depend on it; "
                       "default: the centre of the region's box)", length::dimension)
        .units("m")
        .optional();
    s.number("volume", "the volume V to divide by (m3; 2D: m2), e.g. a body's own volume (default: the region's box)")
        .gt(0)
        .optional();
    profile_param(s, "also the stress, mean velocity and solid fraction in slices of the region's box");
    s.boolean("average", "also the stress (and the profile) averaged over every step since the frame this analysis "
                         "last wrote (impacts between frames included): datasets average/...")
        .fallback(false);
    return s;
  }
  static constexpr const char* doc =
      "mean stress of a region: contact, gravity and inertia terms (de Saxce et al. 2004, valid in dynamics)";

  Stress(const Params& p, const BuildContext& ctx) : dim_(ctx.dimension), sum_(ctx.dimension) {
    if (p.has("origin")) {
      has_origin_ = true;
      const auto o = p.vector("origin");
      for (int k = 0; k < dim_; ++k) origin_[k] = o[k];
    }
    if (p.has("volume")) volume_ = p.number("volume");
    average_ = p.boolean("average");
    bins_ = Bins::parse(p, "profile", dim_);
  }

  bool every_step() const override { return average_; }

  void step(const AnalysisFrame& f, const Region& region) override {
    const Where w = where(f, region);
    const Terms t = terms(f, w.in, w.o);
    Tensor* sums[4] = {&sum_.contact, &sum_.gravity, &sum_.inertia, &sum_.external};
    const Tensor* now[4] = {&t.contact, &t.gravity, &t.inertia, &t.external};
    for (int k = 0; k < 4; ++k)
      for (std::size_t i = 0; i < now[k]->size(); ++i) (*sums[k])[i] += (w.V > 0 ? (*now[k])[i] / w.V : 0.0) * f.h;
    if (bins_.on) {
      const Slices sl = slices(f, w.in, w.lo, w.hi);
      std::vector<double> c, g, i, e;
      std::vector<double>* t4[4] = {&c, &g, &i, &e};
      std::vector<double> vel;
      for (std::size_t k = 0; k < sl.terms.size(); ++k) {
        slice_stress(sl.terms[k], sl.V[k], t4);
        for (int j = 0; j < f.dimension; ++j)
          vel.push_back(sl.terms[k].mass > 0 ? sl.terms[k].momentum[static_cast<std::size_t>(j)] / sl.terms[k].mass : 0.0);
      }
      for (int k = 0; k < 4; ++k) {
        profile_sum_[k].resize(t4[k]->size(), 0.0);
        for (std::size_t q = 0; q < t4[k]->size(); ++q) profile_sum_[k][q] += (*t4[k])[q] * f.h;
      }
      profile_velocity_sum_.resize(vel.size(), 0.0);
      for (std::size_t q = 0; q < vel.size(); ++q) profile_velocity_sum_[q] += vel[q] * f.h;
    }
    summed_time_ += f.h;
    ++summed_steps_;
  }

  void run(const AnalysisFrame& f, const Region& region, AnalysisResult& out) override {
    const int d = f.dimension;
    const Where w = where(f, region);
    // A frame that follows no step (the run's first) has no impulses nor accelerations:
    // the stress is undefined there, NaN.
    const std::vector<char> none(w.in.size(), 0);
    write(out, "", terms(f, f.after_step ? w.in : none, w.o), f.after_step ? w.V : NAN, d);
    out.add("origin", {static_cast<std::size_t>(d)}, std::vector<double>(w.o, w.o + d), "m");
    out.add("box_min", {static_cast<std::size_t>(d)}, std::vector<double>(w.lo, w.lo + d), "m");
    out.add("box_max", {static_cast<std::size_t>(d)}, std::vector<double>(w.hi, w.hi + d), "m");
    if (bins_.on) profile(f, w.in, w.lo, w.hi, out);
    if (average_) {
      const std::size_t n = static_cast<std::size_t>(d);
      const double T = summed_time_;
      auto mean = [&](const Tensor& x) {
        Tensor y(x.size());
        for (std::size_t i = 0; i < x.size(); ++i) y[i] = T > 0 ? x[i] / T : NAN;
        return y;
      };
      Tensor total(n * n);
      for (std::size_t i = 0; i < total.size(); ++i)
        total[i] = sum_.contact[i] + sum_.gravity[i] + sum_.inertia[i] + sum_.external[i];
      out.add("average/total", {n, n}, mean(total), "Pa");
      out.add("average/contact", {n, n}, mean(sum_.contact), "Pa");
      out.add("average/gravity", {n, n}, mean(sum_.gravity), "Pa");
      out.add("average/inertia", {n, n}, mean(sum_.inertia), "Pa");
      out.add("average/external", {n, n}, mean(sum_.external), "Pa");
      out.scalar("average/duration", T, "s");
      out.scalar("average/steps", static_cast<double>(summed_steps_));
      if (bins_.on && !profile_velocity_sum_.empty()) {
        std::vector<double> m4[4];
        const std::vector<double>* c4[4];
        for (int k = 0; k < 4; ++k) {
          for (double x : profile_sum_[k]) m4[k].push_back(x / T);
          c4[k] = &m4[k];
        }
        std::vector<double> vel;
        for (double x : profile_velocity_sum_) vel.push_back(x / T);
        write_profile(out, "average/", d, bins_.count, c4, vel);
      }
      for (auto& p : profile_sum_) p.clear();
      profile_velocity_sum_.clear();
      sum_ = Terms(d);
      summed_time_ = 0;
      summed_steps_ = 0;
    }
  }

 private:
  /// One region's datasets (`prefix` "" or a profile's per-bin arrays are gathered by the caller).
  static void write(AnalysisResult& out, const std::string& prefix, const Terms& t, double V, int d) {
    const std::size_t n = static_cast<std::size_t>(d);
    auto scaled = [&](const Tensor& x) {
      Tensor y(x.size());
      for (std::size_t i = 0; i < x.size(); ++i) y[i] = V > 0 ? x[i] / V : std::isnan(V) ? NAN : 0.0;
      return y;
    };
    Tensor total(static_cast<std::size_t>(d * d));
    for (std::size_t i = 0; i < total.size(); ++i) total[i] = t.contact[i] + t.gravity[i] + t.inertia[i] + t.external[i];
    out.add(prefix + "total", {n, n}, scaled(total), "Pa");
    out.add(prefix + "contact", {n, n}, scaled(t.contact), "Pa");
    out.add(prefix + "gravity", {n, n}, scaled(t.gravity), "Pa");
    out.add(prefix + "inertia", {n, n}, scaled(t.inertia), "Pa");
    out.add(prefix + "external", {n, n}, scaled(t.external), "Pa");
    out.scalar(prefix + "volume", V, d == 2 ? "m2" : "m3");
    out.scalar(prefix + "bodies", static_cast<double>(t.bodies));
    out.scalar(prefix + "solid_fraction", V > 0 ? t.volume_solid / V : 0.0);
    std::vector<double> v(n, 0.0);
    for (std::size_t k = 0; k < n; ++k) v[k] = t.mass > 0 ? t.momentum[k] / t.mass : 0.0;
    out.add(prefix + "velocity", {n}, v, "m/s");
  }

  /// The slices of the region's box along the profile's axis: each one's terms (moments
  /// about its own centre) and volume.
  struct Slices {
    double a = 0, b = 0;
    std::vector<Terms> terms;
    std::vector<double> V;
  };
  Slices slices(const AnalysisFrame& f, const std::vector<char>& in, const double lo[3], const double hi[3]) const {
    const int d = f.dimension, n = bins_.count;
    Slices s;
    bins_.edges(lo, hi, s.a, s.b);
    std::vector<std::vector<char>> member(static_cast<std::size_t>(n), std::vector<char>(in.size(), 0));
    for (std::size_t i = 0; i < in.size(); ++i) {
      if (!in[i]) continue;
      const int k = bins_.bin(f.bodies.position[i * d + bins_.axis], s.a, s.b);
      if (k >= 0) member[static_cast<std::size_t>(k)][i] = 1;
    }
    for (int k = 0; k < n; ++k) {
      double slo[3] = {lo[0], lo[1], lo[2]}, shi[3] = {hi[0], hi[1], hi[2]};
      slo[bins_.axis] = s.a + k * (s.b - s.a) / n;
      shi[bins_.axis] = s.a + (k + 1) * (s.b - s.a) / n;
      double o[3] = {0, 0, 0};
      for (int j = 0; j < d; ++j) o[j] = 0.5 * (slo[j] + shi[j]);
      s.terms.push_back(terms(f, member[static_cast<std::size_t>(k)], o));
      s.V.push_back(f.after_step ? box_volume(slo, shi, d) : NAN);
    }
    return s;
  }

  /// Per slice, row-major: the four terms (contact, gravity, inertia, external) over V.
  static void slice_stress(const Terms& t, double V, std::vector<double>* out[4]) {
    const Tensor* term[4] = {&t.contact, &t.gravity, &t.inertia, &t.external};
    for (int k = 0; k < 4; ++k)
      for (double x : *term[k]) out[k]->push_back(x / V);
  }

  /// Writes `prefix` + profile/... from per-slice stresses (4 terms), velocities and the rest.
  static void write_profile(AnalysisResult& out, const std::string& prefix, int d, int n,
                            const std::vector<double>* terms4[4], const std::vector<double>& velocity) {
    const std::size_t ds = static_cast<std::size_t>(d), nn = static_cast<std::size_t>(n);
    std::vector<double> total(terms4[0]->size(), 0.0);
    for (int k = 0; k < 4; ++k)
      for (std::size_t i = 0; i < total.size(); ++i) total[i] += (*terms4[k])[i];
    out.add(prefix + "profile/total", {nn, ds, ds}, total, "Pa");
    const char* names[4] = {"contact", "gravity", "inertia", "external"};
    for (int k = 0; k < 4; ++k) out.add(prefix + "profile/" + names[k], {nn, ds, ds}, *terms4[k], "Pa");
    out.add(prefix + "profile/velocity", {nn, ds}, velocity, "m/s");
  }

  void profile(const AnalysisFrame& f, const std::vector<char>& in, const double lo[3], const double hi[3],
               AnalysisResult& out) const {
    const int d = f.dimension, n = bins_.count;
    const Slices s = slices(f, in, lo, hi);
    std::vector<double> c, g, i, e, velocity, solid, count;
    std::vector<double>* t4[4] = {&c, &g, &i, &e};
    for (int k = 0; k < n; ++k) {
      const Terms& t = s.terms[static_cast<std::size_t>(k)];
      const double V = s.V[static_cast<std::size_t>(k)];
      slice_stress(t, V, t4);
      for (int j = 0; j < d; ++j) velocity.push_back(t.mass > 0 ? t.momentum[static_cast<std::size_t>(j)] / t.mass : 0.0);
      solid.push_back(t.volume_solid / V);
      count.push_back(static_cast<double>(t.bodies));
    }
    const std::size_t nn = static_cast<std::size_t>(n);
    out.add("profile/position", {nn}, bin_centres(n, s.a, s.b), "m");
    out.scalar("profile/axis", bins_.axis);
    const std::vector<double>* c4[4] = {&c, &g, &i, &e};
    write_profile(out, "", d, n, c4, velocity);
    out.add("profile/solid_fraction", {nn}, solid);
    out.add("profile/bodies", {nn}, count);
  }

  /// The region in a frame: its bodies, box, volume and the origin of the moments.
  struct Where {
    std::vector<char> in;
    double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0}, o[3] = {0, 0, 0};
    double V = 0;
  };
  Where where(const AnalysisFrame& f, const Region& region) const {
    Where w;
    const int d = f.dimension;
    w.in = bodies_in(f, region);
    const bool any = region_box(f, region, w.lo, w.hi);
    for (int k = 0; k < d; ++k) w.o[k] = has_origin_ ? origin_[k] : 0.5 * (w.lo[k] + w.hi[k]);
    w.V = volume_ > 0 ? volume_ : any ? box_volume(w.lo, w.hi, d) : 0.0;
    return w;
  }

  int dim_;
  bool average_ = false;
  Terms sum_{3};  // Σ·h per term since the last frame written (average)
  std::vector<double> profile_sum_[4], profile_velocity_sum_;  // per slice, Σ·h (average with a profile)
  double summed_time_ = 0;
  long summed_steps_ = 0;
  bool has_origin_ = false;
  double volume_ = 0;
  double origin_[3] = {0, 0, 0};
  Bins bins_;
};

MOREAU_REGISTER(Stress, "stress")

}  // namespace

MOREAU_PLUGIN_LIBRARY("moreau_analysis_stress")
