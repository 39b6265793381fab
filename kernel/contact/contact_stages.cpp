#include "contact_stages.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <moreau/error.hpp>
#include <moreau/rigid_fields.hpp>

#include "local_frame.hpp"

namespace moreau::kernel {

namespace R = moreau::rigid;

namespace {
std::uint64_t contact_key(int a, int b, int feature) {
  return (static_cast<std::uint64_t>(a) << 40) | (static_cast<std::uint64_t>(b) << 16) |
         static_cast<std::uint64_t>(feature & 0xffff);
}
}  // namespace

const DetectorUse* ContactStages::detector_for(const std::string& a, const std::string& b) const {
  for (const auto& d : detectors)
    if (d.first == a && d.second == b) return &d;
  return nullptr;
}

void ContactStages::detection_configuration(StepContext& c) {
  // Contacts are detected on the predicted configuration q_θ = q⁻ + (1−θ) h v⁻ (LMGC90's
  // choice): the θ-scheme moves bodies from there by θ h v⁺, so a constraint on v⁺ with
  // the gap at q_θ keeps contacts from closing further during the step.
  const State& st = c.state;
  const int d = st.dimension();
  const std::size_t nb = st.bodies();
  const double a = (1 - c.theta) * c.h;
  poses_.assign(nb * 7, 0.0);
  const double* x = st.field(R::position).data(Depth::begin);
  const double* v = st.field(R::velocity).data(Depth::begin);
  const double* w = st.field(R::angular_velocity).data(Depth::begin);
  const double* q = st.field(d == 2 ? R::angle : R::orientation).data(Depth::begin);
  sweep_.assign(nb, 0.0);
  double g_norm = 0;
  for (double gk : c.gravity) g_norm += gk * gk;
  g_norm = std::sqrt(g_norm);
  for (std::size_t b = 0; b < nb; ++b) {
    double* pose = &poses_[7 * b];
    // How far the body may travel in the step (from its start velocity, with margin):
    // contacts are looked for that much further, so a fast body does not tunnel.
    double v2 = 0;
    for (int k = 0; k < d; ++k) v2 += v[d * b + k] * v[d * b + k];
    sweep_[b] = 2 * c.h * std::sqrt(v2) + c.h * c.h * g_norm;
    for (int k = 0; k < d; ++k) pose[k] = x[d * b + k] + a * v[d * b + k];
    if (d == 2) {
      pose[3] = q[b] + a * w[b];
    } else {
      // q_θ = exp(a ω / 2) ⊗ q⁻ (ω in the world frame); first order is enough for a
      // detection configuration, renormalised.
      const double* qb = q + 4 * b;
      const double* wb = w + 3 * b;
      const double p[4] = {1, 0.5 * a * wb[0], 0.5 * a * wb[1], 0.5 * a * wb[2]};
      double r[4] = {p[0] * qb[0] - p[1] * qb[1] - p[2] * qb[2] - p[3] * qb[3],
                     p[0] * qb[1] + p[1] * qb[0] + p[2] * qb[3] - p[3] * qb[2],
                     p[0] * qb[2] - p[1] * qb[3] + p[2] * qb[0] + p[3] * qb[1],
                     p[0] * qb[3] + p[1] * qb[2] - p[2] * qb[1] + p[3] * qb[0]};
      const double n = 1 / std::sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2] + r[3] * r[3]);
      for (int k = 0; k < 4; ++k) pose[3 + k] = r[k] * n;
    }
  }
  const std::size_t n = contactors.size();
  bp_.dim = d;
  bp_.lo.resize(3 * n);
  bp_.hi.resize(3 * n);
  bp_.body.resize(n);
  bp_.group.resize(n);
  bp_.groups = groups;
  bp_.interacts.resize(static_cast<std::size_t>(groups) * groups);
  for (std::size_t i = 0; i < bp_.interacts.size(); ++i) bp_.interacts[i] = law_of[i] >= 0;
  // Each contactor's world pose: its body's composed with its placement (clusters). An
  // offset contactor also moves by the body's rotation, |ω| |offset| per unit time.
  contactor_poses_.resize(7 * n);
  contactor_sweep_.resize(n);
  const int nr = d == 2 ? 1 : 3;
  for (std::size_t i = 0; i < n; ++i) {
    const Contactor& ct = contactors[i];
    const double* body = &poses_[7 * ct.body];
    double* pose = &contactor_poses_[7 * i];
    contactor_sweep_[i] = sweep_[ct.body];
    if (ct.placement.identity()) {
      std::copy(body, body + 7, pose);
      continue;
    }
    compose_pose(d, body, ct.placement, pose);
    double w2 = 0, o2 = 0;
    for (int k = 0; k < nr; ++k) w2 += w[nr * ct.body + k] * w[nr * ct.body + k];
    for (int k = 0; k < 3; ++k) o2 += ct.placement.offset[k] * ct.placement.offset[k];
    contactor_sweep_[i] += 2 * c.h * std::sqrt(w2 * o2);
  }
  for (std::size_t i = 0; i < n; ++i) {
    const Contactor& ct = contactors[i];
    Pose p{&contactor_poses_[7 * i], &contactor_poses_[7 * i + 3]};
    ct.shape->bounds(d, p, &bp_.lo[3 * i], &bp_.hi[3 * i]);
    for (int k = 0; k < 3; ++k) {  // grow by half the alert distance each, and by the sweep
      bp_.lo[3 * i + k] -= alert / 2 + contactor_sweep_[i];
      bp_.hi[3 * i + k] += alert / 2 + contactor_sweep_[i];
    }
    bp_.body[i] = ct.body;
    bp_.group[i] = ct.group;
  }
}

void ContactStages::broad_phase(StepContext&) { broadphase->pairs(bp_, pairs_); }

void ContactStages::narrow_phase(StepContext& c) {
  const int d = c.state.dimension();
  contacts_.clear();
  for (auto [i, j] : pairs_) {
    const Contactor& a = contactors[i];
    const Contactor& b = contactors[j];
    const DetectorUse* use = detector_for(a.shape->shape_name(), b.shape->shape_name());
    if (!use) continue;  // every pair of interacting shape names has a detector (checked at build)
    const int first = use->swap ? j : i, second = use->swap ? i : j;
    const Contactor& f = contactors[first];
    const Contactor& s = contactors[second];
    scratch_.clear();
    // Contactor poses (body pose ∘ placement); points come back in world coordinates, and
    // the assembly takes lever arms from the body's centre of mass, its origin.
    use->detector->detect(d, *f.shape, Pose{&contactor_poses_[7 * first], &contactor_poses_[7 * first + 3]}, *s.shape,
                          Pose{&contactor_poses_[7 * second], &contactor_poses_[7 * second + 3]},
                          alert + contactor_sweep_[first] + contactor_sweep_[second], scratch_);
    const int law = law_of[f.group * groups + s.group];
    for (const auto& p : scratch_) contacts_.push_back(Detected{{first, second}, p, law, contact_key(first, second, p.feature)});
  }
  if (!initial_overlaps_checked_) warn_initial_overlaps(c);
}

void ContactStages::warn_initial_overlaps(const StepContext& c) {
  // Bodies placed overlapping are pushed apart by the first steps (violently if deep): say
  // which ones, once, at the first step of the run. 1 nm of slack ignores bodies placed
  // exactly touching, whose computed gap is a rounding error.
  initial_overlaps_checked_ = true;
  const auto& names = c.state.names();
  int shown = 0, found = 0;
  for (const auto& ct : contacts_) {
    if (!(ct.point.gap < -(alert + 1e-9))) continue;
    if (++found > 10) continue;
    ++shown;
    const int b0 = contactors[ct.contactor[0]].body, b1 = contactors[ct.contactor[1]].body;
    std::fprintf(stderr, "warning: at the start, bodies \"%s\" and \"%s\" overlap by %.3g m (deeper than the alert distance %.3g m)\n",
                 names[std::min(b0, b1)].c_str(), names[std::max(b0, b1)].c_str(),
                 -ct.point.gap, alert);
  }
  if (found > shown) std::fprintf(stderr, "warning: ... and %d more overlapping contacts at the start\n", found - shown);
}

void ContactStages::warm_start(StepContext& c) {
  const int d = c.state.dimension();
  r_ = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(contacts_.size() * d));
  for (std::size_t a = 0; a < contacts_.size(); ++a) {
    auto it = std::lower_bound(previous_keys_.begin(), previous_keys_.end(), std::make_pair(contacts_[a].key, std::size_t{0}));
    if (it == previous_keys_.end() || it->first != contacts_[a].key) continue;
    for (int k = 0; k < d; ++k) r_[static_cast<Eigen::Index>(a * d + k)] = previous_r_[it->second * d + k];
  }
}

void ContactStages::solve(StepContext& c, const Integrator& integrator) {
  const State& st = c.state;
  const int d = st.dimension();
  const int kk = d == 2 ? 3 : 6;
  const std::size_t nb = st.bodies(), nc = contacts_.size();
  if (nc == 0 && !(exporter && exporter->due(c.step + 1))) {
    // Nothing touches: no bodies to gather, no problem, no impulses (store_reactions
    // tells the integrator so); the step costs the detection only.
    r_.resize(0);
    u_.resize(0);
    report_ = SolverReport{};
    report_.converged = true;
    return;
  }
  RigidBodies bodies;
  bodies.dim = d;
  bodies.com.assign(3 * nb, 0.0);
  bodies.inverse_mass.assign(nb * kk * kk, 0.0);
  bodies.free_velocity.assign(nb * kk, 0.0);
  std::vector<double> v0(nb * kk, 0.0);
  // Only bodies that touch a contact are needed.
  std::vector<char> touched(nb, 0);
  for (const auto& ct : contacts_) touched[contactors[ct.contactor[0]].body] = touched[contactors[ct.contactor[1]].body] = 1;
  const int nr = d == 2 ? 1 : 3;
  const double* vf = st.field(R::free_velocity).data();
  const double* wf = st.field(R::free_angular_velocity).data();
  const double* vb = st.field(R::velocity).data(Depth::begin);
  const double* wb = st.field(R::angular_velocity).data(Depth::begin);
  for (std::size_t b = 0; b < nb; ++b) {
    if (!touched[b]) continue;
    integrator.contact_inverse_mass(st, b, &bodies.inverse_mass[b * kk * kk], &bodies.com[3 * b]);
    for (int k = 0; k < 3; ++k) bodies.com[3 * b + k] = poses_[7 * b + k];  // the detection configuration
    for (int k = 0; k < d; ++k) {
      bodies.free_velocity[b * kk + k] = vf[b * d + k];
      v0[b * kk + k] = vb[b * d + k];
    }
    for (int k = 0; k < nr; ++k) {
      bodies.free_velocity[b * kk + d + k] = wf[b * nr + k];
      v0[b * kk + d + k] = wb[b * nr + k];
    }
  }
  std::vector<RigidContact> rc(nc);
  for (std::size_t a = 0; a < nc; ++a) {
    const auto& p = contacts_[a].point;
    rc[a].body[0] = contactors[contacts_[a].contactor[0]].body;
    rc[a].body[1] = contactors[contacts_[a].contactor[1]].body;
    for (int k = 0; k < 3; ++k) rc[a].point[k] = p.point[k];
    if (d == 2) {
      auto f = local_frame_2d(p.normal);
      for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j) rc[a].frame[i][j] = f[i][j];
    } else {
      auto f = local_frame_3d(p.normal);
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) rc[a].frame[i][j] = f[i][j];
    }
  }
  assembly_.build(bodies, rc, solver->reads_matrix_with_factor());
  problem_.dim = d;
  problem_.W = assembly_.W();
  problem_.q = assembly_.free_local_velocity(bodies);
  problem_.mu.resize(static_cast<Eigen::Index>(nc));
  const Eigen::VectorXd u0 = assembly_.local_velocity(v0);
  for (std::size_t a = 0; a < nc; ++a) {
    const Law& law = *laws[contacts_[a].law];
    problem_.mu[static_cast<Eigen::Index>(a)] = law.friction();
    problem_.q[static_cast<Eigen::Index>(a * d)] +=
        law.normal_shift(LawInput{contacts_[a].point.gap, u0[static_cast<Eigen::Index>(a * d)], c.h});
  }
  assembly_.lend_factor(bodies, problem_.factor);
  // Export (scene key export_problems) while the factor is still lent: W may have to be
  // built from it. The warm start is kept first, since the solver overwrites r_.
  const bool exporting = exporter && exporter->due(c.step + 1);
  const Eigen::VectorXd warm_start = exporting ? r_ : Eigen::VectorXd();
  report_ = solver->solve(problem_, r_, u_);
  if (exporting) exporter->write(c.step + 1, static_cast<double>(c.step + 1) * c.h, c.h, problem_, warm_start, r_, report_);
  assembly_.take_back(problem_.factor);
  for (Eigen::Index i = 0; i < r_.size(); ++i)
    if (!std::isfinite(r_[i])) throw RunError("the contact solver returned non-finite impulses at step " + std::to_string(c.step));
  if (!report_.converged && stop_on_failure)
    throw RunError("the contact solver did not converge at step " + std::to_string(c.step) + " (error " +
                   std::to_string(report_.error) + " after " + std::to_string(report_.iterations) + " iterations)");
}

void ContactStages::store_reactions(StepContext& c) {
  if (contacts_.empty()) {
    c.contact_impulses = false;
    previous_keys_.clear();
    previous_r_.clear();
    return;
  }
  State& st = c.state;
  const int d = st.dimension(), nr = d == 2 ? 1 : 3, kk = d + nr;
  std::vector<double> P;
  assembly_.body_impulses(r_, st.bodies(), P);
  double* imp = st.field(R::impulse).data();
  double* ang = st.field(R::angular_impulse).data();
  for (std::size_t b = 0; b < st.bodies(); ++b) {
    for (int k = 0; k < d; ++k) imp[b * d + k] = P[b * kk + k];
    for (int k = 0; k < nr; ++k) ang[b * nr + k] = P[b * kk + d + k];
  }
  c.contact_impulses = true;
  previous_keys_.clear();
  for (std::size_t a = 0; a < contacts_.size(); ++a) previous_keys_.emplace_back(contacts_[a].key, a);
  std::sort(previous_keys_.begin(), previous_keys_.end());
  previous_r_.assign(r_.data(), r_.data() + r_.size());
}

io::ContactFrame ContactStages::frame(int d, double h) const {
  io::ContactFrame f;
  const std::size_t nc = contacts_.size();
  for (std::size_t a = 0; a < nc; ++a) {
    const auto& ct = contacts_[a];
    f.bodies.push_back(contactors[ct.contactor[0]].body);
    f.bodies.push_back(contactors[ct.contactor[1]].body);
    f.keys.push_back(ct.contactor[0]);
    f.keys.push_back(ct.contactor[1]);
    f.keys.push_back(ct.point.feature);
    for (int k = 0; k < d; ++k) {
      f.point.push_back(ct.point.point[k]);
      f.normal.push_back(ct.point.normal[k]);
    }
    f.gap.push_back(ct.point.gap);
    const double* r = r_.size() ? r_.data() + a * d : nullptr;
    double world[3] = {0, 0, 0};
    double frame_rows[3][3] = {};
    if (d == 2) {
      auto fr = local_frame_2d(ct.point.normal);
      for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j) frame_rows[i][j] = fr[i][j];
    } else {
      auto fr = local_frame_3d(ct.point.normal);
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) frame_rows[i][j] = fr[i][j];
    }
    double rt = 0, ut = 0;
    for (int i = 0; i < d; ++i) {
      const double ri = r ? r[i] : 0.0;
      f.impulse.push_back(ri);
      for (int j = 0; j < d; ++j) world[j] += ri * frame_rows[i][j];
      if (i > 0) {
        rt += ri * ri;
        const double ui = u_.size() ? u_[static_cast<Eigen::Index>(a * d + i)] : 0.0;
        ut += ui * ui;
      }
    }
    for (int j = 0; j < d; ++j) f.force.push_back(world[j] / h);
    const double rn = r ? r[0] : 0.0;
    const double mu = problem_.mu.size() ? problem_.mu[static_cast<Eigen::Index>(a)] : 0.0;
    signed char status = 0;
    if (rn > 0) status = (std::sqrt(ut) > 1e-9 && std::sqrt(rt) >= mu * rn * (1 - 1e-6)) ? 2 : 1;
    f.status.push_back(status);
  }
  return f;
}

void ContactStages::restore(const std::vector<int>& keys, const std::vector<double>& impulses, int d) {
  // A continuation does not start: the overlaps it finds are the run's own (solver
  // tolerance), not the scene's, so the start-of-run warning is not given again.
  initial_overlaps_checked_ = true;
  previous_keys_.clear();
  const std::size_t nc = keys.size() / 3;
  for (std::size_t a = 0; a < nc; ++a) previous_keys_.emplace_back(contact_key(keys[3 * a], keys[3 * a + 1], keys[3 * a + 2]), a);
  std::sort(previous_keys_.begin(), previous_keys_.end());
  previous_r_.assign(impulses.begin(), impulses.begin() + static_cast<std::ptrdiff_t>(nc * d));
}

}  // namespace moreau::kernel
