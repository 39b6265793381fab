#include "frame_view.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <moreau/contact_fields.hpp>
#include <moreau/rigid_fields.hpp>
#include <set>
#include <stdexcept>

#include "../contact/local_frame.hpp"
#include "../contact/placement.hpp"
#include "../run/world.hpp"

namespace moreau::kernel {

namespace R = moreau::rigid;
namespace C = moreau::contact_fields;

FrameView::FrameView(const World& w) {
  const State& st = w.state;
  const int d = st.dimension();
  const std::size_t nb = st.bodies();
  driven_.assign(nb, 0);
  for (const auto& drv : w.drivers) driven_[static_cast<std::size_t>(drv.body)] = 1;
  // Rigid bodies are themselves (one node: centre of mass, rotation, inertia); bodies of
  // other modelizations are boundary to the analyses for now (they will add their nodes).
  rigid_.assign(nb, 0);
  for (std::size_t b = 0; b < nb; ++b) rigid_[b] = st.model_of(b).name == R::model && st.body(b).nodes == 1;

  // Every contactor group of the scene, in the order first met.
  for (const auto& c : w.contactor_info) {
    bool seen = false;
    for (const auto& g : all_groups_) seen = seen || g == c.group;
    if (!seen) all_groups_.push_back(c.group);
  }

  // Volumes and bounding radii from the detected contactors (the shapes the run keeps),
  // about the rigid body's origin (its centre of mass).
  volume_.assign(nb, 0.0);
  radius_.assign(nb, 0.0);
  if (!w.contacts) return;
  const ContactStages& cs = *w.contacts;
  double body_pose[7] = {0, 0, 0, 0, 0, 0, 0};
  if (d == 3) body_pose[3] = 1;  // identity quaternion
  for (const auto& c : cs.contactors) {
    const std::size_t b = static_cast<std::size_t>(c.body);
    if (c.shape->has_mass()) volume_[b] += c.shape->mass_properties().volume;
    double pose[7], lo[3], hi[3];
    compose_pose(d, body_pose, c.placement, pose);
    c.shape->bounds(d, Pose{pose, pose + 3}, lo, hi);
    // The farthest point from the centre, from below: the extent along each axis (exact
    // for disks and spheres) and the display mesh's vertices placed in the body (the
    // corners of polygons and polyhedra). The bounding box's corner would overestimate a
    // disk's by √2 and inflate the whole sample's box.
    double far = 0;
    bool bounded = true;
    for (int k = 0; k < d; ++k) {
      bounded = bounded && std::isfinite(lo[k]) && std::isfinite(hi[k]);
      far = std::max({far, std::fabs(lo[k]), std::fabs(hi[k])});
    }
    if (bounded) {
      const auto R = rotation_matrix(d, c.placement.angle, c.placement.orientation.data());
      const DisplayMesh mesh = c.shape->display_mesh(0.0);
      for (std::size_t v = 0; v + 2 < mesh.points.size(); v += 3) {
        double s = 0;
        for (int i = 0; i < d; ++i) {
          double x = c.placement.offset[static_cast<std::size_t>(i)];
          for (int k = 0; k < 3; ++k) x += R[static_cast<std::size_t>(3 * i + k)] * mesh.points[v + static_cast<std::size_t>(k)];
          s += x * x;
        }
        far = std::max(far, std::sqrt(s));
      }
    }
    radius_[b] = std::max(radius_[b], bounded ? far : std::numeric_limits<double>::infinity());
  }

  // The contact stages number the interacting groups; their names come from the scene's
  // contactors: the detected contactors are, in order, those whose group an interaction
  // names (checked body by body, so a change in how the builder lists them shows here).
  std::set<std::string> interacting;
  if (w.scene.contains("interactions"))
    for (const auto& in : w.scene["interactions"])
      for (const auto& g : in["groups"]) interacting.insert(g.get<std::string>());
  group_names_.assign(static_cast<std::size_t>(cs.groups), "");
  std::size_t j = 0;
  for (const auto& info : w.contactor_info) {
    if (!interacting.count(info.group)) continue;
    if (j >= cs.contactors.size() || cs.contactors[j].body != info.body)
      throw std::logic_error("analyses: the detected contactors do not follow the scene's contactors");
    const int g = cs.contactors[j].group;
    group_names_[static_cast<std::size_t>(g)] = info.group;
    contactor_group_.push_back(g);
    ++j;
  }
  if (j != cs.contactors.size()) throw std::logic_error("analyses: detected contactors left unmatched");
}

const AnalysisFrame& FrameView::build(const World& w, long steps_done, bool after_step) {
  frame_.dimension = w.dimension;
  frame_.step = steps_done;
  frame_.h = w.h;
  frame_.time = static_cast<double>(steps_done) * w.h;
  frame_.theta = w.theta;
  frame_.after_step = after_step;
  frame_.gravity = {0, 0, 0};
  for (int k = 0; k < w.dimension; ++k) frame_.gravity[k] = w.gravity[k];
  frame_.group_names = group_names_;
  bodies(w);
  contacts(w);
  return frame_;
}

void FrameView::bodies(const World& w) {
  // After end_step swapped the depths: Depth::begin holds the step's end values (⁺), and
  // Depth::end still holds its start values (⁻) until the next step overwrites them.
  const State& st = w.state;
  const int d = st.dimension(), r = d == 2 ? 1 : 3, ni = d + r;
  const std::size_t nb = st.bodies();
  mass_.assign(nb, 0.0);
  x_.assign(nb * d, 0.0);
  x0_.assign(nb * d, 0.0);
  v_.assign(nb * d, 0.0);
  v0_.assign(nb * d, 0.0);
  w_.assign(nb * r, 0.0);
  w0_.assign(nb * r, 0.0);
  lever_.assign(nb * d, 0.0);
  second_.assign(nb * d * d, 0.0);
  force_.assign(nb * d, 0.0);
  torque_.assign(nb * r, 0.0);
  sample_.assign(nb, 0);
  const bool forces = !w.forces.empty();
  const double a = (1 - w.theta) * w.h;
  for (std::size_t b = 0; b < nb; ++b) {
    if (!rigid_[b]) {
      // Another modelization: its reference point (the mean of its nodes' positions).
      if (st.has_node_field(b, R::position)) {
        const auto p = st.node_values(b, R::position, Depth::begin);
        const std::size_t n = p.size() / d;
        for (std::size_t i = 0; i < n; ++i)
          for (int k = 0; k < d; ++k) x_[b * d + k] += p[i * d + k] / static_cast<double>(n);
      }
      continue;
    }
    auto copy = [&](const char* name, Depth depth, std::vector<double>& out, int comps) {
      const auto v = st.node_values(b, name, depth);
      for (int k = 0; k < comps; ++k) out[b * comps + k] = v[k];
    };
    copy(R::position, Depth::begin, x_, d);
    copy(R::position, Depth::end, x0_, d);
    copy(R::velocity, Depth::begin, v_, d);
    copy(R::velocity, Depth::end, v0_, d);
    copy(R::angular_velocity, Depth::begin, w_, r);
    copy(R::angular_velocity, Depth::end, w0_, r);
    mass_[b] = st.node_values(b, R::mass)[0];
    // The lever arms of the step's contact impulses start at the detection configuration.
    if (st.has_node_field(b, R::detection_position)) copy(R::detection_position, Depth::end, lever_, d);
    else
      for (int k = 0; k < d; ++k) lever_[b * d + k] = x0_[b * d + k] + a * v0_[b * d + k];
    if (forces) {
      copy(R::force, Depth::end, force_, d);
      copy(R::torque, Depth::end, torque_, r);
    }
    // The sample: bodies that move freely (not fixed, no driver, nothing imposed this step).
    bool free = st.node_values(b, R::fixed)[0] == 0 && !driven_[b];
    if (free && st.has_node_field(b, R::imposed_velocity)) {
      const auto imp = st.node_values(b, R::imposed_velocity);
      for (int k = 0; k < ni; ++k) free = free && std::isnan(imp[k]);
    }
    sample_[b] = free ? 1 : 0;
    // Second moment of mass J = tr(I)/2·1 − I (3D, turned to world axes); 2D: I/2·1.
    const auto I = st.node_values(b, R::inertia);
    if (d == 2) {
      second_[4 * b] = second_[4 * b + 3] = 0.5 * I[0];
    } else {
      const double In[9] = {I[0], I[3], I[4], I[3], I[1], I[5], I[4], I[5], I[2]};
      const double half_trace = 0.5 * (I[0] + I[1] + I[2]);
      double J[9];
      for (int k = 0; k < 9; ++k) J[k] = (k % 4 == 0 ? half_trace : 0.0) - In[k];
      const auto Rm = rotation_matrix(3, 0, st.node_values(b, R::orientation, Depth::begin).data());
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
          double s = 0;
          for (int k = 0; k < 3; ++k)
            for (int l = 0; l < 3; ++l) s += Rm[3 * i + k] * J[3 * k + l] * Rm[3 * j + l];
          second_[9 * b + 3 * i + j] = s;
        }
    }
  }
  AnalysisBodies& B = frame_.bodies;
  B.count = nb;
  B.names = st.names();
  B.mass = mass_;
  B.volume = volume_;
  B.radius = radius_;
  B.sample = sample_;
  B.position = x_;
  B.position_begin = x0_;
  B.lever_position = lever_;
  B.velocity_end = v_;
  B.velocity_begin = v0_;
  B.angular_velocity_end = w_;
  B.angular_velocity_begin = w0_;
  B.second_moment = second_;
  B.force = force_;
  B.torque = torque_;
}

bool FrameView::mesh_side_velocity(const World& w, std::size_t c, double* u_begin, double* u_end) const {
  // The rigid formula above knows only bodies of one node; a side on a mesh moves with the
  // nodes its point sits on, weighted: the contact side's H v, which the step kept.
  const auto b0 = static_cast<std::size_t>(contact_bodies_[2 * c]), b1 = static_cast<std::size_t>(contact_bodies_[2 * c + 1]);
  if ((rigid_[b0] && rigid_[b1]) || !w.contacts) return false;
  const int d = w.dimension;
  const Eigen::VectorXd &ub = w.contacts->local_velocity_begin(), &ue = w.contacts->local_velocity_end();
  const auto need = static_cast<Eigen::Index>((c + 1) * static_cast<std::size_t>(d));
  if (ub.size() != ue.size() || ue.size() < need) return false;
  for (int i = 0; i < d; ++i) {
    const auto k = static_cast<Eigen::Index>(c * static_cast<std::size_t>(d) + static_cast<std::size_t>(i));
    u_begin[i] = ub[k];
    u_end[i] = ue[k];
  }
  return true;
}

void FrameView::contacts(const World& w) {
  AnalysisContacts& Cv = frame_.contacts;
  Cv = AnalysisContacts{};
  const State& st = w.state;
  const int d = w.dimension, r = d == 2 ? 1 : 3;
  // The run's first frame follows no step: whatever a restart loaded into the set is the
  // warm start of the next step, not contacts of this frame.
  const EntitySet* set = frame_.after_step ? st.find_set(sets::contacts) : nullptr;
  const std::size_t nc = set ? set->rows() : 0;
  Cv.count = nc;
  contact_bodies_.assign(nc * 2, 0);
  contact_groups_.assign(nc * 2, 0);
  status_.assign(nc, 0);
  frame_rows_.assign(nc * d * d, 0.0);
  mu_.assign(nc, 0.0);
  u_begin_.assign(nc * d, 0.0);
  u_end_.assign(nc * d, 0.0);
  if (nc == 0) return;
  const double* bodies = set->field(C::bodies).data();
  const double* key = set->field(C::key).data();
  // The μ each contact's law chose for the step (static or dynamic friction).
  static const Eigen::VectorXd no_contacts;
  const Eigen::VectorXd& friction = w.contacts ? w.contacts->last_friction() : no_contacts;
  const double* status = set->field(C::status).data();
  const double* point = set->field(C::point).data();
  const double* normal = set->field(C::normal).data();
  for (std::size_t c = 0; c < nc; ++c) {
    for (int s = 0; s < 2; ++s) {
      contact_bodies_[2 * c + s] = static_cast<int>(bodies[2 * c + s]);
      contact_groups_[2 * c + s] = contactor_group_[static_cast<std::size_t>(key[3 * c + s])];
    }
    status_[c] = static_cast<signed char>(status[c]);
    const auto row = static_cast<Eigen::Index>(c);
    mu_[c] = row < friction.size() ? friction[row] : NAN;
    double* fr = &frame_rows_[c * d * d];
    if (d == 2) {
      const auto f = local_frame_2d(normal + 2 * c);
      for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j) fr[2 * i + j] = f[i][j];
    } else {
      const auto f = local_frame_3d(normal + 3 * c);
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) fr[3 * i + j] = f[i][j];
    }
    // Relative velocity of the material points at the contact, u = Hᵀ v: first body minus
    // second, each v + ω × (x_c − x_lever), in the local frame; with a side on another
    // modelization (a mesh), the contact side's own H v (mesh_side_velocity).
    if (mesh_side_velocity(w, c, &u_begin_[c * d], &u_end_[c * d])) continue;
    for (int depth = 0; depth < 2; ++depth) {
      const auto& v = depth == 0 ? v0_ : v_;
      const auto& om = depth == 0 ? w0_ : w_;
      double rel[3] = {0, 0, 0};
      for (int s = 0; s < 2; ++s) {
        const std::size_t b = static_cast<std::size_t>(contact_bodies_[2 * c + s]);
        const double sign = s == 0 ? 1.0 : -1.0;
        double arm[3] = {0, 0, 0}, wv[3] = {0, 0, 0};
        for (int k = 0; k < d; ++k) arm[k] = point[c * d + k] - lever_[b * d + k];
        if (d == 2) {
          wv[0] = -om[b] * arm[1];
          wv[1] = om[b] * arm[0];
        } else {
          const double* o = &om[b * r];
          wv[0] = o[1] * arm[2] - o[2] * arm[1];
          wv[1] = o[2] * arm[0] - o[0] * arm[2];
          wv[2] = o[0] * arm[1] - o[1] * arm[0];
        }
        for (int k = 0; k < d; ++k) rel[k] += sign * (v[b * d + k] + wv[k]);
      }
      double* u = depth == 0 ? &u_begin_[c * d] : &u_end_[c * d];
      for (int i = 0; i < d; ++i) {
        double s = 0;
        for (int k = 0; k < d; ++k) s += fr[d * i + k] * rel[k];
        u[i] = s;
      }
    }
  }
  Cv.bodies = contact_bodies_;
  Cv.groups = contact_groups_;
  Cv.point = {point, nc * d};
  Cv.frame = frame_rows_;
  Cv.impulse = {set->field(C::impulse).data(), nc * d};
  Cv.mu = mu_;
  Cv.gap = {set->field(C::gap).data(), nc};
  Cv.status = status_;
  Cv.velocity_begin = u_begin_;
  Cv.velocity_end = u_end_;
}

}  // namespace moreau::kernel
