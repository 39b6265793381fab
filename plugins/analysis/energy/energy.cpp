// `energy`: the energy balance of the sample (the bodies that move freely: not fixed, not
// driven), accumulated over every step since the run (or its restart) began:
//
//   T + V − (T₀ + V₀) = W_ext + W_boundary + W_θ − D_impacts − D_friction   (+ balance_error)
//
// T = Σ ½ m v² + ½ ωᵀ I ω, V = −Σ m g·x. Over a step, with ū = (u⁻ + u⁺)/2 the mean local
// relative velocity at a contact (u = Hᵀv) and r its impulse:
//   D_impacts  += −r_n ū_n          (normal part: impacts, and contacts closing)
//   D_friction += −r_t · ū_t        (tangential part: friction)
//   W_boundary += −Σ p_s · w̄_s over the contacts' sides s on fixed, driven or deformable
//                 bodies (their material-point velocity w̄ at the contact): the work walls,
//                 pistons and meshes do on the sample
//   W_ext      += h (F · v̄ + τ · ω̄)  (force plugins)
//   W_θ        += h (½ − θ) m g · (v⁺ − v⁻)  (the θ-scheme's own work; 0 for θ = ½; it telescopes
//                 to h (½ − θ) Σ m g · (v − v₀): a boundary term, not a dissipation)
// In 2D, and in 3D for bodies with isotropic inertia (spheres), this is the θ-scheme's
// discrete energy identity: the balance closes to rounding whatever the solver's error.
// In 3D the gyroscopic term of other bodies adds an O(h) residual, reported in
// balance_error. Only the whole sample is allowed: bodies crossing a box would carry
// energy in and out.
#include <moreau/analysis.hpp>
#include <moreau/error.hpp>

namespace {

using namespace moreau;

struct Energies {
  double translational = 0, rotational = 0, potential = 0;
  double total() const { return translational + rotational + potential; }
};

/// The sample's energies, at the end of the step (`end`) or at its start.
Energies energies(const AnalysisFrame& f, bool end) {
  const int d = f.dimension, r = d == 2 ? 1 : 3;
  const auto& B = f.bodies;
  const auto& v = end ? B.velocity_end : B.velocity_begin;
  const auto& w = end ? B.angular_velocity_end : B.angular_velocity_begin;
  const auto& x = end ? B.position : B.position_begin;
  Energies e;
  for (std::size_t b = 0; b < B.count; ++b) {
    if (!B.sample[b]) continue;
    double v2 = 0, gx = 0;
    for (int k = 0; k < d; ++k) {
      v2 += v[b * d + k] * v[b * d + k];
      gx += f.gravity[static_cast<std::size_t>(k)] * x[b * d + k];
    }
    e.translational += 0.5 * B.mass[b] * v2;
    e.potential -= B.mass[b] * gx;
    const double* J = &B.second_moment[b * d * d];
    if (d == 2) {
      e.rotational += 0.5 * (J[0] + J[3]) * w[b] * w[b];  // I = tr J
    } else {
      const double* o = &w[b * r];
      const double tr = J[0] + J[4] + J[8];
      double s = 0;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) s += o[i] * ((i == j ? tr : 0.0) - J[3 * i + j]) * o[j];
      e.rotational += 0.5 * s;
    }
  }
  return e;
}

/// The material-point velocity at contact c of its side s, a boundary body (fixed, driven,
/// or deformable: the analyses see a mesh as boundary), at the step's start or end: the
/// other side's (a sample body's) point velocity minus the relative velocity the contact
/// measured, u = first − second (local frame, turned to world axes). For a rigid wall this
/// is its own point velocity; for a mesh it is the velocity of its nodes weighted at the
/// contact, which the analysis cannot see itself. With it Σ p·v̄ of the sample splits
/// exactly into the boundary's work and the contacts' dissipation.
void boundary_velocity(const AnalysisFrame& f, std::size_t c, int s, bool end, double out[3]) {
  const int d = f.dimension;
  const auto& C = f.contacts;
  const std::size_t other = static_cast<std::size_t>(C.bodies[2 * c + (s == 0 ? 1 : 0)]);
  point_velocity(f, other, &C.point[c * d], end, out);
  const double* u = &(end ? C.velocity_end : C.velocity_begin)[c * d];
  const double sign = s == 0 ? 1.0 : -1.0;  // boundary first: w = v_other + u; second: w = v_other − u
  for (int i = 0; i < d; ++i)
    for (int j = 0; j < d; ++j) out[j] += sign * C.frame[(c * d + i) * d + j] * u[i];
}

class Energy : public Analysis {
 public:
  static Schema schema() { return {}; }
  static constexpr const char* doc =
      "energy balance of the sample: kinetic, potential, dissipated by impacts and by friction, work of walls and forces";

  Energy(const Params&, const BuildContext&) {}

  void prepare(const AnalysisSetup& s) override {
    if (!s.region.whole)
      throw InputError(s.region_pointer, "the energy balance is for the whole sample (bodies crossing a box would carry "
                                         "energy in and out): leave out \"region\" or give \"all\"");
  }
  bool every_step() const override { return true; }

  void step(const AnalysisFrame& f, const Region&) override {
    if (!started_) start(energies(f, false));
    const int d = f.dimension, r = d == 2 ? 1 : 3;
    const auto& B = f.bodies;
    const double h = f.h;
    for (std::size_t b = 0; b < B.count; ++b) {
      if (!B.sample[b]) continue;
      for (int k = 0; k < d; ++k) {
        const double dv = B.velocity_end[b * d + k] - B.velocity_begin[b * d + k];
        const double vm = 0.5 * (B.velocity_end[b * d + k] + B.velocity_begin[b * d + k]);
        theta_ += h * (0.5 - f.theta) * B.mass[b] * f.gravity[static_cast<std::size_t>(k)] * dv;
        external_ += h * B.force[b * d + k] * vm;
      }
      for (int k = 0; k < r; ++k)
        external_ += h * B.torque[b * r + k] * 0.5 * (B.angular_velocity_end[b * r + k] + B.angular_velocity_begin[b * r + k]);
    }
    const auto& C = f.contacts;
    for (std::size_t c = 0; c < C.count; ++c) {
      const std::size_t b0 = static_cast<std::size_t>(C.bodies[2 * c]), b1 = static_cast<std::size_t>(C.bodies[2 * c + 1]);
      if (!B.sample[b0] && !B.sample[b1]) continue;  // between two walls: not the sample's energy
      const double* p = &C.impulse[c * d];
      impacts_ -= p[0] * 0.5 * (C.velocity_begin[c * d] + C.velocity_end[c * d]);
      for (int i = 1; i < d; ++i) friction_ -= p[i] * 0.5 * (C.velocity_begin[c * d + i] + C.velocity_end[c * d + i]);
      for (int s = 0; s < 2; ++s) {
        const std::size_t b = s == 0 ? b0 : b1;
        if (B.sample[b]) continue;
        double w0[3], w1[3], pw[3] = {0, 0, 0};
        boundary_velocity(f, c, s, false, w0);
        boundary_velocity(f, c, s, true, w1);
        for (int i = 0; i < d; ++i)
          for (int j = 0; j < d; ++j) pw[j] += C.frame[(c * d + i) * d + j] * p[i];
        const double sign = s == 0 ? 1.0 : -1.0;
        for (int j = 0; j < d; ++j) boundary_ -= sign * pw[j] * 0.5 * (w0[j] + w1[j]);
      }
    }
  }

  void run(const AnalysisFrame& f, const Region&, AnalysisResult& out) override {
    const Energies e = energies(f, true);
    if (!started_) start(e);
    const std::string J = f.dimension == 2 ? "J/m" : "J";
    out.scalar("kinetic", e.translational + e.rotational, J);
    out.scalar("kinetic_rotational", e.rotational, J);
    out.scalar("potential", e.potential, J);
    out.scalar("initial", initial_, J);
    out.scalar("dissipated_impacts", impacts_, J);
    out.scalar("dissipated_friction", friction_, J);
    out.scalar("work_external", external_, J);
    out.scalar("work_boundary", boundary_, J);
    out.scalar("work_theta", theta_, J);
    out.scalar("balance_error", e.total() - initial_ - (external_ + boundary_ + theta_ - impacts_ - friction_), J);
  }

 private:
  void start(const Energies& e) {
    started_ = true;
    initial_ = e.total();
  }
  bool started_ = false;
  double initial_ = 0, impacts_ = 0, friction_ = 0, external_ = 0, boundary_ = 0, theta_ = 0;
};

MOREAU_REGISTER(Energy, "energy")

}  // namespace

MOREAU_PLUGIN_LIBRARY("moreau_analysis_energy")
