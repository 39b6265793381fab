#include "contact_stages.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <cstdio>
#include <tuple>
#include <moreau/contact_error.hpp>
#include <moreau/error.hpp>
#include <moreau/contact_fields.hpp>
#include <moreau/node_fields.hpp>

#include "../run/console.hpp"
#include "../run/stage_timer.hpp"
#include "local_frame.hpp"
#include "stopping_scale.hpp"

namespace moreau::kernel {

namespace C = moreau::contact_fields;

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
  // Each modelization's integrator wrote where its nodes are at the detection
  // configuration (node fields detection_position, detection_rotation, travel); a
  // contactor's world pose is its node's composed with its placement (clusters).
  const State& st = c.state;
  const int d = st.dimension();
  struct NodeFields {
    const double *x = nullptr, *q = nullptr, *travel = nullptr;
  };
  std::vector<NodeFields> nf(models.size());
  for (std::size_t m = 0; m < models.size(); ++m) {
    const EntitySet& set = st.set(models[m].nodes);
    if (const Field* f = set.find(node_fields::detection_position)) nf[m].x = f->data();
    if (const Field* f = set.find(node_fields::detection_rotation)) nf[m].q = f->data();
    if (const Field* f = set.find(node_fields::travel)) nf[m].travel = f->data();
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
  // Each contactor's world pose: its node's composed with its placement (clusters). An
  // offset contactor also moves by the node's rotation: the angle turned times |offset|.
  contactor_poses_.resize(7 * n);
  contactor_sweep_.resize(n);
  const int nr = d == 2 ? 1 : 4;
  facet_index_.assign(n, -1);
  facet_points_.clear();
  for (std::size_t i = 0; i < n; ++i) {
    const Contactor& ct = contactors[i];
    const NodeFields& f = nf[ct.model];
    double node[7] = {0, 0, 0, 1, 0, 0, 0};
    if (d == 2) node[3] = 0;
    if (ct.count > 1) {
      // A mesh facet: placed by its nodes (Pose::nodes); it may travel as far as its
      // farthest-moving node.
      facet_index_[i] = static_cast<long>(facet_points_.size());
      facet_points_.resize(facet_points_.size() + 12, 0.0);
      double* points = &facet_points_[static_cast<std::size_t>(facet_index_[i])];
      contactor_sweep_[i] = 0;
      for (int j = 0; j < ct.count; ++j) {
        for (int k = 0; k < d; ++k) points[3 * j + k] = f.x[d * ct.nodes[j] + k];
        if (f.travel) contactor_sweep_[i] = std::max(contactor_sweep_[i], f.travel[2 * ct.nodes[j]]);
      }
      for (int k = 0; k < d; ++k) node[k] = points[k];
      std::copy(node, node + 7, &contactor_poses_[7 * i]);
      continue;
    }
    for (int k = 0; k < d; ++k) node[k] = f.x[d * ct.node + k];
    if (f.q)
      for (int k = 0; k < nr; ++k) node[3 + k] = f.q[nr * ct.node + k];
    double* pose = &contactor_poses_[7 * i];
    contactor_sweep_[i] = f.travel ? f.travel[2 * ct.node] : 0.0;
    if (ct.placement.identity()) {
      std::copy(node, node + 7, pose);
      continue;
    }
    compose_pose(d, node, ct.placement, pose);
    double o2 = 0;
    for (int k = 0; k < 3; ++k) o2 += ct.placement.offset[k] * ct.placement.offset[k];
    if (f.travel) contactor_sweep_[i] += f.travel[2 * ct.node + 1] * std::sqrt(o2);
  }
  for (std::size_t i = 0; i < n; ++i) {
    const Contactor& ct = contactors[i];
    ct.shape->bounds(d, pose_of(i), &bp_.lo[3 * i], &bp_.hi[3 * i]);
    for (int k = 0; k < 3; ++k) {  // grow by half the alert distance each, and by the sweep
      bp_.lo[3 * i + k] -= alert / 2 + contactor_sweep_[i];
      bp_.hi[3 * i + k] += alert / 2 + contactor_sweep_[i];
    }
    bp_.body[i] = ct.body;
    bp_.group[i] = ct.group;
  }
  swept_.begin_step(contactors, models, st, c.theta, c.h);
}

void ContactStages::broad_phase(StepContext&) { broadphase->pairs(bp_, pairs_); }

void ContactStages::index_shape_kinds() {
  std::vector<std::string> names;
  shape_kind_.resize(contactors.size());
  for (std::size_t i = 0; i < contactors.size(); ++i) {
    const std::string name = contactors[i].shape->shape_name();
    const auto at = std::find(names.begin(), names.end(), name);
    shape_kind_[i] = static_cast<int>(at - names.begin());
    if (at == names.end()) names.push_back(name);
  }
  kinds_ = names.size();
  kind_detector_.resize(kinds_ * kinds_);
  for (std::size_t a = 0; a < kinds_; ++a)
    for (std::size_t b = 0; b < kinds_; ++b) kind_detector_[a * kinds_ + b] = detector_for(names[a], names[b]);
}

void ContactStages::narrow_phase(StepContext& c) {
  const int d = c.state.dimension();
  contacts_.clear();
  if (shape_kind_.size() != contactors.size()) index_shape_kinds();  // contactors are built once
  for (auto [i, j] : pairs_) {
    const DetectorUse* use = kind_detector_[static_cast<std::size_t>(shape_kind_[i]) * kinds_ + static_cast<std::size_t>(shape_kind_[j])];
    if (!use) continue;  // every pair of interacting shape names has a detector (checked at build)
    const int first = use->swap ? j : i, second = use->swap ? i : j;
    const Contactor& f = contactors[first];
    const Contactor& s = contactors[second];
    scratch_.clear();
    start_gaps_.clear();
    const double reach = alert + contactor_sweep_[first] + contactor_sweep_[second];
    // A pair fast enough to cross a shape before q_θ is followed from q⁻ instead.
    const bool swept = swept_.fast(first, second) &&
                       swept_.detect(d, *use->detector, contactors, first, second, reach, scratch_, start_gaps_);
    // Contactor poses (body pose ∘ placement); points come back in world coordinates, and
    // the assembly takes lever arms from the body's centre of mass, its origin.
    if (!swept)
      use->detector->detect(d, *f.shape, pose_of(static_cast<std::size_t>(first)), *s.shape,
                            pose_of(static_cast<std::size_t>(second)), reach, scratch_);
    const int law = law_of[f.group * groups + s.group];
    for (std::size_t k = 0; k < scratch_.size(); ++k) {
      const auto& p = scratch_[k];
      contacts_.push_back(Detected{{first, second}, p, law, contact_key(first, second, p.feature), swept,
                                   swept ? start_gaps_[k] : p.gap});
    }
  }
  if (!facet_points_.empty()) keep_nearest_facets();
  if (!initial_overlaps_checked_) warn_initial_overlaps(c);
}

Pose ContactStages::pose_of(std::size_t i) const {
  Pose p{&contactor_poses_[7 * i], &contactor_poses_[7 * i + 3]};
  if (facet_index_[i] >= 0) {
    p.nodes = &facet_points_[static_cast<std::size_t>(facet_index_[i])];
    p.node_count = contactors[i].count;
  }
  return p;
}

namespace {

/// The support nodes of a facet contact (its facet's nodes of non-zero weight), as a bit
/// mask over the facet's nodes.
unsigned facet_support(const Contactor& facet, const ContactPoint& p, int side) {
  unsigned mask = 0;
  for (int j = 0; j < facet.count; ++j)
    if (p.weights[side][j] != 0) mask |= 1u << j;
  return mask;
}

}  // namespace

void ContactStages::drop_corners_of_nearer_facets(std::vector<char>& drop) const {
  // A candidate that projects inside facet A (or onto an edge of a 3D face) is also found
  // by a neighbouring facet B past B's end, at the corner (or edge) B shares with A. The
  // point of A is then at least as near as that corner (the corner is part of A), so the
  // corner contact is never the nearest feature; but by |gap| it can win: a disk resting
  // in the valley of a sagging mesh (gap −1e-10 inside A, +1e-11 at the corner, which the
  // disk then rolls about as about a pinnacle, unstably, until it falls through). Drop a
  // facet contact whose support nodes all belong to another contact's facet (same
  // candidate, same body) that supports that candidate on more of its nodes.
  struct Support {
    int candidate, feature, body;
    std::size_t index;
    std::array<std::size_t, 4> nodes;  ///< the support nodes (rows of the node set)
    int count;                         ///< how many
    const Contactor* facet;
  };
  std::vector<Support> supports;
  for (std::size_t a = 0; a < contacts_.size(); ++a) {
    const Detected& ct = contacts_[a];
    const bool f0 = facet_index_[ct.contactor[0]] >= 0, f1 = facet_index_[ct.contactor[1]] >= 0;
    if (f0 == f1) continue;
    const int side = f0 ? 0 : 1;
    const Contactor& facet = contactors[ct.contactor[side]];
    const unsigned mask = facet_support(facet, ct.point, side);
    Support s{ct.contactor[1 - side], ct.point.feature, facet.body, a, {}, 0, &facet};
    for (int j = 0; j < facet.count; ++j)
      if (mask & (1u << j)) s.nodes[static_cast<std::size_t>(s.count++)] = facet.nodes[static_cast<std::size_t>(j)];
    supports.push_back(s);
  }
  std::sort(supports.begin(), supports.end(),
            [](const Support& x, const Support& y) {
              return std::tie(x.candidate, x.feature, x.body, x.index) < std::tie(y.candidate, y.feature, y.body, y.index);
            });
  for (std::size_t i = 0; i < supports.size();) {
    std::size_t j = i;
    while (j < supports.size() && supports[j].candidate == supports[i].candidate && supports[j].feature == supports[i].feature &&
           supports[j].body == supports[i].body)
      ++j;
    for (std::size_t x = i; x < j; ++x)
      for (std::size_t y = i; y < j; ++y) {
        const Support &X = supports[x], &Y = supports[y];
        if (x == y || Y.count <= X.count || drop[Y.index]) continue;
        bool inside = true;  // every support node of X is a node of Y's facet
        for (int k = 0; k < X.count && inside; ++k)
          inside = std::find(Y.facet->nodes.begin(), Y.facet->nodes.begin() + Y.facet->count, X.nodes[k]) !=
                   Y.facet->nodes.begin() + Y.facet->count;
        if (inside) {
          drop[X.index] = 1;
          break;
        }
      }
    i = j;
  }
}

bool ContactStages::inside_facet_in_front(const Detected& ct) const {
  // In a concave part of a mesh boundary (a valley of a sagging beam, the dent a disk
  // presses into a slab) a round candidate projects inside several facets and touches
  // each: all those contacts hold it (one alone leaves it penetrating the others, or
  // rocking across the valley). A contact inside its facet, with the candidate's centre in
  // front of the facet's plane (gap ≥ −half width), is such a contact, kept beside the
  // nearest. One behind the plane (a node that crossed a convex corner of the other mesh,
  // seen from the far facet) is not: the nearest alone stays.
  const int side = facet_index_[ct.contactor[0]] >= 0 ? 0 : 1;
  const Contactor& facet = contactors[ct.contactor[side]];
  const unsigned all = (1u << facet.count) - 1;
  if (facet_support(facet, ct.point, side) != all) return false;
  const int d = facet.count == 2 ? 2 : 3;
  return ct.point.gap >= -contactors[ct.contactor[1 - side]].shape->half_width(d);
}

void ContactStages::keep_nearest_facets() {
  // A candidate (a mesh node, a disk, a sphere, a corner of a polygon, box or convex
  // shape: its feature) near a mesh boundary is found against each facet close enough: of
  // its contacts with the facets of one body, the corners of nearer facets go
  // (drop_corners_of_nearer_facets), then the one of smallest |gap| stays (ties: the first
  // found), as LMGC90 keeps the nearest antagonist segment, with the others inside their
  // facets in front of them (inside_facet_in_front; docs/contacts.md, "Meshes").
  struct Entry {
    int candidate, feature, body;
    double distance;
    std::size_t index;
  };
  std::vector<char> drop(contacts_.size(), 0);
  drop_corners_of_nearer_facets(drop);
  std::vector<Entry> entries;
  for (std::size_t a = 0; a < contacts_.size(); ++a) {
    const Detected& ct = contacts_[a];
    const bool f0 = facet_index_[ct.contactor[0]] >= 0, f1 = facet_index_[ct.contactor[1]] >= 0;
    if (f0 == f1 || drop[a]) continue;
    const int facet = ct.contactor[f0 ? 0 : 1], other = ct.contactor[f0 ? 1 : 0];
    entries.push_back(Entry{other, ct.point.feature, contactors[facet].body, std::fabs(ct.point.gap), a});
  }
  std::sort(entries.begin(), entries.end(), [](const Entry& x, const Entry& y) {
    return std::tie(x.candidate, x.feature, x.body, x.distance, x.index) <
           std::tie(y.candidate, y.feature, y.body, y.distance, y.index);
  });
  // The others kept beside the nearest must hold the candidate in another direction: two
  // contacts of one round candidate whose normals differ by less than 0.01 rad (a disk
  // across the valley of a nearly flat, sagging beam) constrain the same motion, and such
  // near-duplicates only slow the solvers down; without the second, the candidate overlaps
  // that facet by at most ~R·0.01² near the valley's node.
  constexpr double same_direction = 0.99995;  // cos 0.01
  std::size_t nearest = 0;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    if (i == 0 || entries[i].candidate != entries[i - 1].candidate || entries[i].feature != entries[i - 1].feature ||
        entries[i].body != entries[i - 1].body) {
      nearest = entries[i].index;
      continue;
    }
    const Detected& ct = contacts_[entries[i].index];
    double cosine = 0;
    for (int k = 0; k < 3; ++k) cosine += ct.point.normal[k] * contacts_[nearest].point.normal[k];
    if (!inside_facet_in_front(ct) || cosine > same_direction) drop[entries[i].index] = 1;
  }
  std::size_t kept = 0;
  for (std::size_t a = 0; a < contacts_.size(); ++a)
    if (!drop[a]) contacts_[kept++] = contacts_[a];
  contacts_.resize(kept);
}

void ContactStages::warn_initial_overlaps(const StepContext& c) {
  // Bodies placed overlapping are pushed apart by the first steps (violently if deep): say
  // which ones, once, at the first step of the run. 1 nm of slack ignores bodies placed
  // exactly touching, whose computed gap is a rounding error.
  initial_overlaps_checked_ = true;
  const auto& names = c.state.names();
  int shown = 0, found = 0;
  for (const auto& ct : contacts_) {
    if (!(ct.start_gap < -(alert + 1e-9))) continue;
    if (++found > 10) continue;
    ++shown;
    const int b0 = contactors[ct.contactor[0]].body, b1 = contactors[ct.contactor[1]].body;
    char line[512];
    std::snprintf(line, sizeof line, "at the start, bodies \"%s\" and \"%s\" overlap by %.3g m (deeper than the alert distance %.3g m)",
                  names[std::min(b0, b1)].c_str(), names[std::max(b0, b1)].c_str(), -ct.start_gap, alert);
    warn(line);
  }
  if (found > shown) warn("... and " + std::to_string(found - shown) + " more overlapping contacts at the start");
}

/// A swept contact whose end-of-step position asks a faster departure than its law does
/// (docs/contacts.md, "Fast bodies": with θ < 1 the committed (1−θ)h v⁻ already reaches
/// the other body, so the body leaves at up to (1−θ)/θ of its approach speed, whatever e).
/// Said once per run, when it is more than 1 % of the approach speed.
void ContactStages::warn_swept_rebound(const StepContext& c, const Detected& ct, double approach, double law_shift,
                                       double shift) {
  if (swept_rebound_warned_ || law_shift - shift <= 0.01 * std::fabs(approach)) return;
  swept_rebound_warned_ = true;
  const auto& names = c.state.names();
  const int b0 = contactors[ct.contactor[0]].body, b1 = contactors[ct.contactor[1]].body;
  char line[768];
  std::snprintf(line, sizeof line,
                "step %ld: bodies \"%s\" and \"%s\" met within the step at %.3g m/s (swept detection); to end "
                "the step touching rather than inside or past each other they leave at %.3g m/s at least, where "
                "the law asks %.3g m/s: with theta = %g the time step is too coarse for this impact (a smaller "
                "time step, or theta = 1, resolves it; docs/contacts.md, \"Fast bodies\"; said once per run)",
                c.step + 1, names[std::min(b0, b1)].c_str(), names[std::max(b0, b1)].c_str(), -approach, -shift,
                std::max(0.0, -law_shift), c.theta);
  warn(line);
}

void ContactStages::warm_start(StepContext& c) {
  // This step's contacts become the rows of the `contacts` set. A contact that persists
  // (same key as a row of the previous step) continues that row: its persistent fields
  // (the impulse, the solver's warm start) are carried over; the others are new.
  State& st = c.state;
  const int d = st.dimension();
  EntitySet& set = st.set(sets::contacts);
  const std::size_t nc = contacts_.size();
  const ContactFieldRefs& f = resolved(contact_fields_, set);
  {
    const double* kv = f.key->data(Depth::begin);
    previous_keys_.clear();
    for (std::size_t a = 0; a < set.rows(); ++a)
      previous_keys_.emplace_back(contact_key(static_cast<int>(kv[3 * a]), static_cast<int>(kv[3 * a + 1]),
                                              static_cast<int>(kv[3 * a + 2])),
                                  static_cast<std::ptrdiff_t>(a));
    std::sort(previous_keys_.begin(), previous_keys_.end());
  }
  std::vector<std::ptrdiff_t> from(nc, -1);
  new_contact_.assign(nc, 1);
  for (std::size_t a = 0; a < nc; ++a) {
    auto it = std::lower_bound(previous_keys_.begin(), previous_keys_.end(), std::make_pair(contacts_[a].key, std::ptrdiff_t{-1}));
    if (it != previous_keys_.end() && it->first == contacts_[a].key) {
      from[a] = it->second;
      new_contact_[a] = 0;
    }
  }
  continue_nearby(set, from);
  set.rebuild(from);
  double* bodies = f.bodies->data();
  double* key = f.key->data();
  double* point = f.point->data();
  double* normal = f.normal->data();
  double* gap = f.gap->data();
  double* law = f.law->data();
  for (std::size_t a = 0; a < nc; ++a) {
    const Detected& ct = contacts_[a];
    bodies[2 * a] = contactors[ct.contactor[0]].body;
    bodies[2 * a + 1] = contactors[ct.contactor[1]].body;
    key[3 * a] = ct.contactor[0];
    key[3 * a + 1] = ct.contactor[1];
    key[3 * a + 2] = ct.point.feature;
    for (int k = 0; k < d; ++k) {
      point[d * a + k] = ct.point.point[k];
      normal[d * a + k] = ct.point.normal[k];
    }
    gap[a] = ct.point.gap;
    law[a] = ct.law;
  }
  const double* impulse = f.impulse->data();
  r_ = Eigen::Map<const Eigen::VectorXd>(impulse, static_cast<Eigen::Index>(nc * d));
}

ContactStages::ContactFieldRefs ContactStages::ContactFieldRefs::of(EntitySet& set) {
  ContactFieldRefs f;
  f.key = &set.field(C::key);  // (each throws when the set lacks it, as the lookups by name did)
  f.bodies = &set.field(C::bodies);
  f.point = &set.field(C::point);
  f.normal = &set.field(C::normal);
  f.gap = &set.field(C::gap);
  f.law = &set.field(C::law);
  f.impulse = &set.field(C::impulse);
  f.force = &set.field(C::force);
  f.normal_force = &set.field(C::normal_force);
  f.status = &set.field(C::status);
  f.velocity = &set.field(C::velocity);
  f.cache_key.take(set);
  return f;
}

void ContactStages::continue_nearby(const EntitySet& set, std::vector<std::ptrdiff_t>& from) {
  // A face contact's points change feature when the faces' roles flip (which one clips
  // the other) or, in 3D, when a clipped polygon's corners change: the contact is the same
  // place of the same two contactors. For laws that keep per-contact variables (a bond, a
  // damage), a new contact continues the nearest row of the same two contactors that no
  // contact continued, when it is within the distance the pair may move in a step.
  if (!law_step_.keeps_variables()) return;
  const std::size_t nc = contacts_.size(), rows = set.rows();
  std::vector<char> taken(rows, 0);
  bool any_new = false;
  for (std::size_t a = 0; a < nc; ++a) {
    if (from[a] >= 0) taken[static_cast<std::size_t>(from[a])] = 1;
    else any_new = any_new || law_step_.keeps_variables(contacts_[a].law);
  }
  if (!any_new) return;
  const int d = set.field(C::point).components();
  const double* kv = set.field(C::key).data(Depth::begin);
  const double* old_point = set.field(C::point).data(Depth::begin);
  for (std::size_t a = 0; a < nc; ++a) {
    if (from[a] >= 0 || !law_step_.keeps_variables(contacts_[a].law)) continue;
    const Detected& ct = contacts_[a];
    const double reach = alert + contactor_sweep_[ct.contactor[0]] + contactor_sweep_[ct.contactor[1]] + 1e-9;
    std::ptrdiff_t best = -1;
    double best_d2 = reach * reach;
    for (std::size_t r = 0; r < rows; ++r) {
      if (taken[r] || kv[3 * r] != ct.contactor[0] || kv[3 * r + 1] != ct.contactor[1]) continue;
      double d2 = 0;
      for (int k = 0; k < d; ++k) d2 += (old_point[d * r + k] - ct.point.point[k]) * (old_point[d * r + k] - ct.point.point[k]);
      if (d2 <= best_d2) best_d2 = d2, best = static_cast<std::ptrdiff_t>(r);
    }
    if (best < 0) continue;
    from[a] = best;
    taken[static_cast<std::size_t>(best)] = 1;
    new_contact_[a] = 0;
  }
}

void ContactStages::setup_solver(State& state) {
  const std::vector<FieldSpec> fields = solver->state_fields(state.dimension());
  if (fields.empty()) return;
  EntitySet& set = state.add_set(sets::solver);
  for (FieldSpec f : fields) {
    f.set = sets::solver;
    f.depths = 1;
    f.output = FieldOutput::frame;
    f.restart = true;
    f.persist = false;
    f.needed = Needed::always;
    set.declare(f);
  }
  if (set.rows() == 0) set.add_rows(1);
  solver->save_state(set);  // a new run's state, in the first frame
  solver_state_ = true;
}

void ContactStages::restored(State& state, bool solver_state) {
  initial_overlaps_checked_ = true;
  if (solver_state_ && solver_state) solver->load_state(state.set(sets::solver));
}

void ContactStages::solve(StepContext& c) {
  const State& st = c.state;
  const int d = st.dimension();
  const std::size_t nc = contacts_.size();
  if (nc == 0 && !(exporter && exporter->due(c.step + 1))) {
    // Nothing touches: no problem, no impulses (store_reactions tells the integrators so);
    // the step costs the detection only.
    r_.resize(0);
    u_.resize(0);
    report_ = SolverReport{};
    report_.converged = true;
    law_step_.no_contacts(c.state);
    return;
  }
  fill_sides(d);
  const auto t0 = StageClock::now();
  assembly_.build(st, models, sides_, solver->reads_matrix_with_factor(), problem_);
  assembly_seconds_ += std::chrono::duration<double>(StageClock::now() - t0).count();
  q_free_ = assembly_.local_velocity(st, Velocity::free);
  u_begin_ = assembly_.local_velocity(st, Velocity::begin);
  assembly_.lend(problem_);
  solve_with_laws(c);
  assembly_.take_back(problem_);
  if (solver_state_) solver->save_state(c.state.set(sets::solver));
  for (Eigen::Index i = 0; i < r_.size(); ++i)
    if (!std::isfinite(r_[i])) throw RunError("the contact solver returned non-finite impulses at step " + std::to_string(c.step));
  // With "on_failure": "stop" a miss ends the run below: the error message says it all.
  if (report_.converged || !stop_on_failure)
    solve_log.record(c.step + 1, report_, [&] { return worst_contact_bodies(c.state); });
  if (!report_.converged && stop_on_failure)
    throw RunError("the contact solver did not converge at step " + std::to_string(c.step + 1) + " (error " +
                   scientific(report_.error) + " after " + std::to_string(report_.iterations) + " iterations)");
}

std::string ContactStages::worst_contact_bodies(const State& st) const {
  // The contact whose one-contact natural map is largest: where the solve is worst.
  const int d = problem_.dim;
  double worst = -1;
  std::size_t at = 0;
  // In the solver's variables (the laws' change of variables, law_step.hpp).
  const Eigen::VectorXd &r = law_step_.solver_impulse(), &u = law_step_.solver_velocity();
  if (u.size() != r.size() || r.size() != static_cast<Eigen::Index>(contacts_.size() * d)) return "";
  for (std::size_t a = 0; a < contacts_.size(); ++a) {
    const double e = contact_natural_map_squared(d, problem_.mu[static_cast<Eigen::Index>(a)], r.data() + a * d, u.data() + a * d);
    if (e > worst) worst = e, at = a;
  }
  if (worst < 0) return "";
  const auto& names = st.names();
  return "\"" + names[contactors[contacts_[at].contactor[0]].body] + "\" and \"" +
         names[contactors[contacts_[at].contactor[1]].body] + "\"";
}

/// Swept contacts whose gap at q_θ is negative may not end the step overlapping: their
/// normal shift is capped at g/(θh) (swept_shift). False when no contact needs it.
bool ContactStages::swept_caps(const StepContext& c) {
  const double none = std::numeric_limits<double>::infinity();
  swept_caps_.assign(contacts_.size(), none);
  bool any = false;
  for (std::size_t a = 0; a < contacts_.size(); ++a)
    if (contacts_[a].swept) {
      swept_caps_[a] = swept_shift(none, contacts_[a].point.gap, c.theta, c.h);
      any = any || swept_caps_[a] < none;
    }
  return any;
}

void ContactStages::solve_with_laws(StepContext& c) {
  // The laws' terms make the standard problem the solver sees (law_step.hpp); a law whose
  // internal variables the solution changes (damage, bonds that break) has the step
  // solved again, from the last answer, until they agree.
  const std::size_t nc = contacts_.size();
  contact_law_.resize(nc);
  contact_gap_.resize(nc);
  for (std::size_t a = 0; a < nc; ++a) {
    contact_law_[a] = contacts_[a].law;
    contact_gap_[a] = contacts_[a].point.gap;
  }
  law_step_.begin(c.state, c.step, c.h, c.theta, contact_law_, contact_gap_, u_begin_, q_free_, new_contact_);
  law_step_.cap_normal_shift(swept_caps(c) ? &swept_caps_ : nullptr);
  // Export (scene key export_problems) while the factor is still lent: W may have to be
  // built from it. The warm start is kept first, since the solver overwrites r_.
  const bool exporting = exporter && exporter->due(c.step + 1);
  Eigen::VectorXd warm_start, solved;
  long iterations = 0;
  for (int solves = 1;; ++solves) {
    law_step_.to_solver(problem_, r_);
    if (law_step_.capped() >= 0) {
      const auto a = static_cast<std::size_t>(law_step_.capped());
      warn_swept_rebound(c, contacts_[a], u_begin_[static_cast<Eigen::Index>(a * c.state.dimension())],
                         law_step_.capped_law_shift(), swept_caps_[a]);
    }
    problem_.error_scale = approaching_contacts_scale(problem_);
    if (exporting) warm_start = r_;
    report_ = shadows ? shadows->solve(*solver, problem_, r_, u_) : solver->solve(problem_, r_, u_);
    if (exporting) solved = r_;  // the answer in the solver's variables
    iterations += report_.iterations;
    law_step_.from_solver(problem_, r_, u_, report_.error);
    if (!law_step_.update(r_, u_)) break;
    if (solves == law_solves_per_step) {
      if (!laws_warned_)
        std::fprintf(stderr, "warning: step %ld: the contact laws' internal variables still change after %d solves of "
                             "the step; its last solve is kept (docs/laws.md)\n", c.step, solves);
      laws_warned_ = true;
      break;
    }
  }
  report_.iterations = iterations;
  law_step_.finish(c.state);
  // The problem as the solver saw it last (the laws' standard form), and its answer.
  if (exporting) export_problem(c, warm_start, solved);
}

void ContactStages::export_problem(const StepContext& c, const Eigen::VectorXd& warm_start, const Eigen::VectorXd& solved) {
  const long step = c.step + 1;
  const double t = static_cast<double>(step) * c.h;
  if (exporter->settings().global) {
    assembly_.take_back(problem_);  // H, lent to the solver's factor, is the assembly's again
    const fclib::GlobalProblem g = assembly_.global_problem(c.state, problem_.q, problem_.mu);
    assembly_.lend(problem_);
    exporter->write_global(step, t, c.h, g, warm_start, solved, report_);
  } else
    exporter->write(step, t, c.h, problem_, warm_start, solved, report_);
}

void ContactStages::fill_sides(int d) {
  const std::size_t nc = contacts_.size();
  sides_.clear();
  sides_.frame.resize(nc * d * d);
  const bool facets = !facet_points_.empty();
  for (std::size_t a = 0; a < nc; ++a) {
    const auto& p = contacts_[a].point;
    for (int side = 0; side < 2; ++side) {
      const Contactor& ct = contactors[contacts_[a].contactor[side]];
      sides_.body.push_back(ct.body);
      sides_.model.push_back(ct.model);
      sides_.node.push_back(ct.node);
      if (!facets) continue;
      // Points on mesh facets: the facet's nodes with the detector's weights.
      sides_.count.push_back(ct.count);
      for (int j = 0; j < 4; ++j) {
        sides_.nodes.push_back(ct.count > 1 ? ct.nodes[j] : ct.node);
        sides_.weights.push_back(ct.count > 1 ? p.weights[side][j] : (j == 0 ? 1.0 : 0.0));
      }
    }
    for (int k = 0; k < 3; ++k) sides_.point.push_back(p.point[k]);
    double* fr = &sides_.frame[a * d * d];
    if (d == 2) {
      auto f = local_frame_2d(p.normal);
      for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j) fr[i * 2 + j] = f[i][j];
    } else {
      auto f = local_frame_3d(p.normal);
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) fr[i * 3 + j] = f[i][j];
    }
  }
}

void ContactStages::store_reactions(StepContext& c) {
  State& st = c.state;
  if (contacts_.empty()) {
    c.contact_impulses = false;
    return;
  }
  const int d = st.dimension();
  assembly_.store_reactions(st, r_);
  c.contact_impulses = true;
  // The contacts' own results: the impulse (next step's warm start), the world force, the
  // local velocity and the status.
  const ContactFieldRefs& f = resolved(contact_fields_, st.set(sets::contacts));
  double* impulse = f.impulse->data();
  double* force = f.force->data();
  double* normal_force = f.normal_force->data();
  double* status = f.status->data();
  double* velocity = f.velocity->data();
  const double* normal = f.normal->data();
  for (std::size_t a = 0; a < contacts_.size(); ++a) {
    const double* r = r_.data() + a * d;
    double frame_rows[3][3] = {};
    if (d == 2) {
      auto fr = local_frame_2d(normal + d * a);
      for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j) frame_rows[i][j] = fr[i][j];
    } else {
      auto fr = local_frame_3d(normal + d * a);
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) frame_rows[i][j] = fr[i][j];
    }
    double world[3] = {0, 0, 0};
    for (int i = 0; i < d; ++i) {
      impulse[d * a + i] = r[i];
      velocity[d * a + i] = u_[static_cast<Eigen::Index>(a * d + i)];
      for (int j = 0; j < d; ++j) world[j] += r[i] * frame_rows[i][j];
    }
    for (int j = 0; j < d; ++j) force[d * a + j] = world[j] / c.h;
    normal_force[a] = r[0] / c.h;
    status[a] = law_step_.status(a);  // in the solver's variables (a bond in tension is closed)
  }
}

}  // namespace moreau::kernel
