#pragma once
// Analyses (plugin kind `analysis`): what a run's contacts and bodies mean as continuum
// quantities — mean stress, polarization of contact forces, fabric, wall loads, energy.
// A scene lists them under `analyses`; each runs at output frames (every N-th, key
// `every`) on a region (key `region`: the whole sample or a box) and writes named
// datasets into the frame, under /frames/NNNNNNNN/analyses/<name>/ (docs/analyses.md).
//
// An analysis never reads the kernel's storage: it sees a frame through AnalysisFrame,
// plain arrays the kernel fills from its state (bodies) and the step's contacts. Rigid
// bodies appear as themselves; a deformable body will appear as its nodes, point masses
// with no rotation (second moment zero), so an analysis written against this view serves
// both without change.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <moreau/plugin.hpp>
#include <span>
#include <string>
#include <vector>

namespace moreau {

/// The bodies of a frame. Rows are bodies; d is the dimension, r the number of rotation
/// components (1 in 2D, 3 in 3D). Values are those after the frame's step: "end" is the
/// end of that step (⁺), "begin" its start (⁻); at the first frame of a run both are the
/// initial state.
struct AnalysisBodies {
  std::size_t count = 0;
  std::span<const std::string> names;
  std::span<const double> mass;    ///< [nb] kg (2D: per unit thickness); 0 for fixed bodies given none
  std::span<const double> volume;  ///< [nb] m³ (2D: m², per unit thickness): solid volume of the contactors
  /// [nb] m: bounding radius about `position`, the distance to the farthest point of the
  /// body's shapes (a disk's or sphere's radius, a polygon's circumradius; infinite for half-spaces)
  std::span<const double> radius;
  /// [nb] 1 for the bodies of the sample: they move freely (not fixed, no driver). Fixed and
  /// driven bodies are the boundary: their contacts with the sample are boundary tractions.
  std::span<const char> sample;
  std::span<const double> position;        ///< [nb×d] m, centre of mass at the end of the step
  std::span<const double> position_begin;  ///< [nb×d] m, at the start of the step
  /// [nb×d] m: the centre of mass at the step's detection configuration, x⁻ + (1−θ) h v⁻,
  /// about which the step's contact impulses act (their lever arms start here).
  std::span<const double> lever_position;
  std::span<const double> velocity_begin, velocity_end;                  ///< [nb×d] m/s
  std::span<const double> angular_velocity_begin, angular_velocity_end;  ///< [nb×r] rad/s, world frame
  /// [nb×d×d] kg m² (2D: per unit thickness): second moment of mass about the centre of
  /// mass, J = ∫ρ y⊗y dV, world axes (the inertia tensor is tr(J)·1 − J). In 2D only the
  /// polar inertia is known: J = (I/2)·1, exact for disks and regular polygons.
  std::span<const double> second_moment;
  /// [nb×d], [nb×r]: the step's external forces and torques (force plugins), world frame,
  /// N and N m; zeros when the scene has none.
  std::span<const double> force, torque;
};

/// The contacts of the frame's step (the impulses the solver found for it).
struct AnalysisContacts {
  std::size_t count = 0;
  std::span<const int> bodies;  ///< [nc×2] body indices; the impulse acts on the first, its opposite on the second
  std::span<const int> groups;  ///< [nc×2] contactor group of each side: index into AnalysisFrame::group_names
  std::span<const double> point;  ///< [nc×d] m, world, at the step's detection configuration
  /// [nc×d×d] the local frame, rows in world axes: the normal (unit, from the second body
  /// toward the first), then the tangent(s). Local vectors v_loc = frame · v_world.
  std::span<const double> frame;
  std::span<const double> impulse;  ///< [nc×d] N s, local frame (normal first); force = impulse / h
  std::span<const double> mu;       ///< [nc] Coulomb friction coefficient the contact's law chose for the step
  std::span<const double> gap;      ///< [nc] m, at detection
  std::span<const signed char> status;  ///< [nc] 0 open, 1 sticking, 2 sliding (as written in the frame)
  /// [nc×d] m/s, local frame: relative velocity (first minus second) of the two bodies'
  /// material points at the contact point, from the velocities at the start (begin) and
  /// end of the step: u = Hᵀ v with the step's H.
  std::span<const double> velocity_begin, velocity_end;
};

struct AnalysisFrame {
  int dimension = 3;
  long step = 0;     ///< steps done (the frame's name)
  double time = 0;   ///< s, = step · h
  double h = 0;      ///< s, time step
  double theta = 0.5;
  /// False at a run's first frame (step 0, or the frame a restart starts from): no step was
  /// computed, so there are no contacts and "begin" values equal "end" values.
  bool after_step = true;
  std::array<double, 3> gravity{0, 0, 0};  ///< m/s² (2D: z is 0)
  std::span<const std::string> group_names;  ///< contactor groups that interact
  AnalysisBodies bodies;
  AnalysisContacts contacts;
};

/// An analysis's region (scene key `region`): the whole sample, or an axis-aligned box.
struct Region {
  bool whole = true;
  std::array<double, 3> lo{0, 0, 0}, hi{0, 0, 0};  ///< box corners (2D: z unused)
  bool contains(const double* x, int dim) const {
    if (whole) return true;
    for (int k = 0; k < dim; ++k)
      if (x[k] < lo[k] || x[k] > hi[k]) return false;
    return true;
  }
};

/// One dataset an analysis writes into its group of the frame. `name` may hold '/' to make
/// subgroups ("profile/total"). Either numbers (`values`, row-major, `shape` empty for a
/// scalar) or strings (`strings`, a 1-D dataset).
struct AnalysisDataset {
  std::string name;
  std::vector<std::size_t> shape;
  std::vector<double> values;
  std::vector<std::string> strings;
  std::string units;  ///< written as the dataset's `units` attribute ("" for none)
};

struct AnalysisResult {
  std::vector<AnalysisDataset> datasets;
  void add(std::string name, std::vector<std::size_t> shape, std::vector<double> values, std::string units = "") {
    datasets.push_back({std::move(name), std::move(shape), std::move(values), {}, std::move(units)});
  }
  void scalar(std::string name, double value, std::string units = "") { add(std::move(name), {}, {value}, std::move(units)); }
  void strings(std::string name, std::vector<std::string> values) {
    datasets.push_back({std::move(name), {values.size()}, {}, std::move(values), ""});
  }
};

/// What an analysis learns about the scene once, before the run, to check its parameters
/// (unknown bodies or groups: throw InputError at a pointer below `pointer`).
struct AnalysisSetup {
  int dimension = 3;
  std::vector<std::string> body_names;  ///< every body, in scene order
  std::vector<std::string> groups;      ///< every contactor group of the scene
  std::vector<std::string> group_names; ///< the groups that interact (AnalysisFrame::group_names)
  std::vector<std::array<std::string, 2>> interactions;  ///< the scene's interacting group pairs, in order
  Region region;
  std::string pointer;         ///< of this analysis in the scene (/analyses/i)
  std::string region_pointer;  ///< of its region (/analyses/i/region)
};

class MOREAU_API Analysis : public Plugin {
 public:
  static constexpr Kind kind = Kind::analysis;
  /// Once, after the scene is built: check names against the scene.
  virtual void prepare(const AnalysisSetup&) {}
  /// True to have step() called after every step (e.g. to accumulate dissipated energy);
  /// it then also sees the steps between the frames it writes.
  virtual bool every_step() const { return false; }
  virtual void step(const AnalysisFrame& frame, const Region& region) {
    (void)frame;
    (void)region;
  }
  /// At a frame this analysis is due: its results, written to its group of the frame.
  virtual void run(const AnalysisFrame& frame, const Region& region, AnalysisResult& out) = 0;
};

// ---- helpers every analysis needs ------------------------------------------------------

/// Sample bodies whose centre (end of step) lies in the region.
inline std::vector<char> bodies_in(const AnalysisFrame& f, const Region& r) {
  const int d = f.dimension;
  std::vector<char> in(f.bodies.count, 0);
  for (std::size_t b = 0; b < f.bodies.count; ++b)
    in[b] = f.bodies.sample[b] && r.contains(&f.bodies.position[b * d], d);
  return in;
}

/// The region's box: its own, or for the whole sample the box around the sample bodies'
/// extents (centre ± bounding radius) in this frame. False when the sample is empty.
inline bool region_box(const AnalysisFrame& f, const Region& r, double lo[3], double hi[3]) {
  const int d = f.dimension;
  for (int k = 0; k < 3; ++k) lo[k] = r.lo[k], hi[k] = r.hi[k];
  if (!r.whole) return true;
  bool any = false;
  for (std::size_t b = 0; b < f.bodies.count; ++b) {
    if (!f.bodies.sample[b]) continue;
    const double rad = std::isfinite(f.bodies.radius[b]) ? f.bodies.radius[b] : 0.0;
    for (int k = 0; k < d; ++k) {
      const double x = f.bodies.position[b * d + k];
      lo[k] = any ? std::min(lo[k], x - rad) : x - rad;
      hi[k] = any ? std::max(hi[k], x + rad) : x + rad;
    }
    any = true;
  }
  return any;
}

/// Volume of a box (2D: area, per unit thickness).
inline double box_volume(const double lo[3], const double hi[3], int dim) {
  double v = 1;
  for (int k = 0; k < dim; ++k) v *= hi[k] - lo[k];
  return v;
}

/// World force of contact c on its first body (N): frameᵀ · impulse / h.
inline void contact_force(const AnalysisFrame& f, std::size_t c, double out[3]) {
  const int d = f.dimension;
  out[0] = out[1] = out[2] = 0;
  for (int i = 0; i < d; ++i)
    for (int j = 0; j < d; ++j) out[j] += f.contacts.frame[(c * d + i) * d + j] * f.contacts.impulse[c * d + i] / f.h;
}

/// Velocity (m/s, world) of the material point of body b at x, at the start (`end` false)
/// or end of the step: v + ω × (x − lever position).
inline void point_velocity(const AnalysisFrame& f, std::size_t b, const double* x, bool end, double out[3]) {
  const int d = f.dimension, r = d == 2 ? 1 : 3;
  const auto& v = end ? f.bodies.velocity_end : f.bodies.velocity_begin;
  const auto& w = end ? f.bodies.angular_velocity_end : f.bodies.angular_velocity_begin;
  double a[3] = {0, 0, 0};
  for (int k = 0; k < d; ++k) a[k] = x[k] - f.bodies.lever_position[b * d + k];
  out[2] = 0;
  if (d == 2) {
    out[0] = v[b * 2] - w[b] * a[1];
    out[1] = v[b * 2 + 1] + w[b] * a[0];
  } else {
    const double* o = &w[b * r];
    out[0] = v[b * 3] + o[1] * a[2] - o[2] * a[1];
    out[1] = v[b * 3 + 1] + o[2] * a[0] - o[0] * a[2];
    out[2] = v[b * 3 + 2] + o[0] * a[1] - o[1] * a[0];
  }
}

/// ‖r_t‖ / (μ r_n) of contact c: 0 for an open contact, 1 on the cone's boundary; a
/// frictionless closed contact (μ = 0) is on the boundary, 1.
inline double mobilisation(const AnalysisFrame& f, std::size_t c) {
  const int d = f.dimension;
  const double* r = &f.contacts.impulse[c * d];
  if (!(r[0] > 0)) return 0;
  double rt = 0;
  for (int i = 1; i < d; ++i) rt += r[i] * r[i];
  rt = std::sqrt(rt);
  const double mu = f.contacts.mu[c];
  if (mu <= 0) return 1;
  return rt / (mu * r[0]);
}

}  // namespace moreau
