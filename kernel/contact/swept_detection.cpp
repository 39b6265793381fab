#include "swept_detection.hpp"

#include <algorithm>
#include <cmath>
#include <moreau/node_fields.hpp>
#include <moreau/rigid_fields.hpp>
#include <string>

#include "../run/console.hpp"
#include "contact_stages.hpp"

namespace moreau::kernel {

namespace R = moreau::rigid;

namespace {
/// Conservative advancement stops this close (times the thinner half width) and carries
/// the contact on to first order. Where the detector reports nothing (a face clipped
/// against nothing: a polygon beside a wall's end) it advances by a lower bound of the
/// distance, or by half the thinner half width if that is more (an overlap that shallow
/// keeps its normal). It gives up after this many advances (then the pair keeps the
/// contacts of q_θ, and the run is told).
constexpr double touch_fraction = 0.25;
constexpr int max_advances = 4096;

/// The velocity of the material point p of a body at x moving at v, w (world frame).
void point_velocity(int d, const double* x, const double* v, const double* w, const double* p, double* out) {
  const double r[3] = {p[0] - x[0], p[1] - x[1], d == 3 ? p[2] - x[2] : 0.0};
  if (d == 2) {
    out[0] = v[0] - w[0] * r[1];
    out[1] = v[1] + w[0] * r[0];
    out[2] = 0;
  } else {
    out[0] = v[0] + w[1] * r[2] - w[2] * r[1];
    out[1] = v[1] + w[2] * r[0] - w[0] * r[2];
    out[2] = v[2] + w[0] * r[1] - w[1] * r[0];
  }
}

double norm(const double* a, int n) {
  double s = 0;
  for (int k = 0; k < n; ++k) s += a[k] * a[k];
  return std::sqrt(s);
}
}  // namespace

void advance_pose(int d, const double* x, const double* v, const double* q, const double* w, double t, double* pose) {
  for (int k = 0; k < d; ++k) pose[k] = x[k] + t * v[k];
  if (d == 2) {
    pose[2] = 0;
    pose[3] = q[0] + t * w[0];
    pose[4] = pose[5] = pose[6] = 0;
    return;
  }
  const double p[4] = {1, 0.5 * t * w[0], 0.5 * t * w[1], 0.5 * t * w[2]};
  double r[4];
  quat_product(p, q, r);
  const double n = 1 / std::sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2] + r[3] * r[3]);
  for (int k = 0; k < 4; ++k) pose[3 + k] = r[k] * n;
}

void SweptDetection::begin_step(const std::vector<Contactor>& contactors, const std::vector<ContactModel>& models,
                                const State& st, double theta, double h) {
  dim_ = st.dimension();
  step_ = h;
  travel_time_ = (1 - theta) * h;
  contactors_ = &contactors;
  if (half_width_.size() != contactors.size()) {
    const std::size_t n = contactors.size();
    half_width_.resize(n);
    reach_.resize(n);
    radius_.resize(n);
    on_mesh_.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      const Contactor& c = contactors[i];
      on_mesh_[i] = c.count > 1 || st.body(static_cast<std::size_t>(c.body)).nodes > 1;
      if (on_mesh_[i]) {  // no pose of its own (a facet's bounds need its nodes), never swept
        half_width_[i] = radius_[i] = reach_[i] = 0;
        continue;
      }
      half_width_[i] = c.shape->half_width(dim_);
      const double zero[4] = {0, 0, 0, 0}, identity[4] = {1, 0, 0, 0};
      double lo[3], hi[3];
      c.shape->bounds(dim_, Pose{zero, dim_ == 2 ? zero : identity}, lo, hi);
      double corner = 0;
      for (int k = 0; k < dim_; ++k) corner += std::max(lo[k] * lo[k], hi[k] * hi[k]);
      radius_[i] = std::sqrt(corner);
      reach_[i] = norm(c.placement.offset.data(), 3) + radius_[i];
    }
  }
  nodes_.assign(models.size(), Nodes{});
  for (std::size_t m = 0; m < models.size(); ++m) {
    const EntitySet& set = st.set(models[m].nodes);
    auto at_start = [&](const char* name) {
      const Field* f = set.find(name);
      return f ? f->data(Depth::begin) : nullptr;
    };
    nodes_[m] = {at_start(node_fields::position), at_start(dim_ == 2 ? node_fields::angle : node_fields::orientation),
                 at_start(R::velocity), at_start(R::angular_velocity)};
  }
}

const double* SweptDetection::x_of(int i) const {
  const Contactor& c = (*contactors_)[i];
  return nodes_[c.model].x + dim_ * c.node;
}

const double* SweptDetection::v_of(int i) const {
  static const double still[3] = {0, 0, 0};
  const Contactor& c = (*contactors_)[i];
  return nodes_[c.model].v ? nodes_[c.model].v + dim_ * c.node : still;
}

const double* SweptDetection::w_of(int i) const {
  static const double still[3] = {0, 0, 0};
  const Contactor& c = (*contactors_)[i];
  const int nr = dim_ == 2 ? 1 : 3;
  return nodes_[c.model].w ? nodes_[c.model].w + nr * c.node : still;
}

double SweptDetection::distance_bound(const Shape& a, int i, const double* pa, const Shape& b, int j,
                                      const double* pb) const {
  double alo[3], ahi[3], blo[3], bhi[3];
  a.bounds(dim_, Pose{pa, pa + 3}, alo, ahi);
  b.bounds(dim_, Pose{pb, pb + 3}, blo, bhi);
  double boxes = 0, centres = 0;
  for (int k = 0; k < dim_; ++k) {
    const double g = std::max({0.0, blo[k] - ahi[k], alo[k] - bhi[k]});
    if (std::isfinite(g)) boxes += g * g;
    centres += (pa[k] - pb[k]) * (pa[k] - pb[k]);
  }
  const double spheres = std::sqrt(centres) - radius_[i] - radius_[j];  // −∞ for a half-space: no bound
  return std::max(std::sqrt(boxes), std::isnan(spheres) ? 0.0 : spheres);
}

double SweptDetection::approach_speed(int i, int j) const {
  // Any two material points of the pair approach at most at |v_a − v_b| + |ω_a| ρ_a + |ω_b| ρ_b.
  const int d = dim_, nr = d == 2 ? 1 : 3;
  const double *va = v_of(i), *vb = v_of(j);
  double dv[3] = {0, 0, 0};
  for (int k = 0; k < d; ++k) dv[k] = va[k] - vb[k];
  double s = norm(dv, d);
  const double wa = norm(w_of(i), nr), wb = norm(w_of(j), nr);
  if (wa > 0) s += wa * reach_[i];
  if (wb > 0) s += wb * reach_[j];
  return s;
}

bool SweptDetection::fast(int i, int j) const {
  if (on_mesh_[static_cast<std::size_t>(i)] || on_mesh_[static_cast<std::size_t>(j)]) return false;  // header
  if (!nodes_[(*contactors_)[i].model].x || !nodes_[(*contactors_)[j].model].x) return false;
  // Predicted past or deep enough in the other for its normal to flip takes a travel of
  // about the sum of the half widths (a disk's centre reaching a wall's mid-line); half of
  // it leaves a margin of two. Infinite for a half-space, which cannot be crossed.
  return step_ * approach_speed(i, j) > 0.5 * (half_width_[i] + half_width_[j]);
}

void SweptDetection::contactor_pose(int i, double t, double* pose) const {
  const Contactor& c = (*contactors_)[i];
  const int d = dim_;
  const Nodes& n = nodes_[c.model];
  static const double no_rotation[4] = {1, 0, 0, 0}, no_angle[1] = {0};
  const double* q = n.q ? n.q + (d == 2 ? 1 : 4) * c.node : (d == 2 ? no_angle : no_rotation);
  double node[7];
  advance_pose(d, x_of(i), v_of(i), q, w_of(i), t, node);
  if (c.placement.identity()) std::copy(node, node + 7, pose);
  else compose_pose(d, node, c.placement, pose);
}

bool SweptDetection::detect(int d, const Detector& detector, const std::vector<Contactor>& contactors, int first,
                            int second, double alert, std::vector<ContactPoint>& out, std::vector<double>& start_gap) {
  const Contactor& f = contactors[first];
  const Contactor& s = contactors[second];
  const double speed = approach_speed(first, second);
  const double thinner = std::min(half_width_[first], half_width_[second]), tol = touch_fraction * thinner;
  double t = 0, distance_at_start = 0;
  bool touching = false;
  for (int it = 0; it < max_advances && !touching; ++it) {
    double pf[7], ps[7];
    contactor_pose(first, t, pf);
    contactor_pose(second, t, ps);
    scratch_.clear();
    detector.detect(d, *f.shape, Pose{pf, pf + 3}, *s.shape, Pose{ps, ps + 3}, alert, scratch_);
    double advance;
    if (scratch_.empty()) {
      // Nothing reported: apart by more than `alert`, or beside a face. A lower bound of
      // the distance (bounding boxes, bounding spheres) is safe to advance by.
      const double lb = distance_bound(*f.shape, first, pf, *s.shape, second, ps);
      if (lb > alert) return false;  // the detection distance covers the step's travel
      advance = std::max(lb, 0.5 * thinner);
      if (it == 0) distance_at_start = std::max(lb, tol);
    } else {
      double gap = scratch_.front().gap;
      for (const auto& p : scratch_) gap = std::min(gap, p.gap);
      if (it == 0) distance_at_start = gap;
      touching = gap <= tol;
      advance = gap;
    }
    if (touching) break;
    t += advance / speed;
    if (t >= step_) return false;
  }
  if (!touching) {
    if (unconverged_++ == 0)
      warn("swept detection gave up following a fast pair (contactors " + std::to_string(first) + " and " +
           std::to_string(second) + ", " + std::to_string(max_advances) +
           " advances): its contacts are those of the predicted configuration, which a body this fast may pass "
           "through; a smaller time step avoids it (said once per run)");
    return false;
  }
  // Touching at t: carry each point to q_θ (time T, before or after t) along the bodies' motion.
  const double *x0a = x_of(first), *x0b = x_of(second), *v0a = v_of(first), *v0b = v_of(second);
  double xa[3] = {0, 0, 0}, xb[3] = {0, 0, 0};
  for (int k = 0; k < d; ++k) {
    xa[k] = x0a[k] + t * v0a[k];
    xb[k] = x0b[k] + t * v0b[k];
  }
  const double rest = travel_time_ - t;
  // The point follows the node that travels more, by its translation: a contact point is
  // not a material point (a rolling disk's stays under its centre), and the lever arms
  // the solve takes from q_θ's centres stay as they were at the touch.
  const double* moving = norm(v0a, d) >= norm(v0b, d) ? v0a : v0b;
  for (ContactPoint p : scratch_) {
    double va[3], vb[3];
    point_velocity(d, xa, v0a, w_of(first), p.point, va);
    point_velocity(d, xb, v0b, w_of(second), p.point, vb);
    double un = 0;
    for (int k = 0; k < d; ++k) un += p.normal[k] * (va[k] - vb[k]);
    start_gap.push_back(t == 0 ? p.gap : distance_at_start);
    p.gap += rest * un;
    for (int k = 0; k < d; ++k) p.point[k] += rest * moving[k];
    out.push_back(p);
  }
  return true;
}

}  // namespace moreau::kernel
