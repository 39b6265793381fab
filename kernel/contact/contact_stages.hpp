#pragma once
// The contact stages of a step (DESIGN §1): detection configuration, broad phase, narrow
// phase, warm start, solve, store reactions. Built only for scenes with interactions.
// The kernel's side of the seed's InteractionHandler: contactors are supported by nodes of
// the modelizations' node sets; the contacts of a step are the rows of the State's
// `contacts` set (moreau/contact_fields.hpp), rebuilt at warm_start with what persists
// carried over by identity; the problem is built from the modelizations' pieces
// (contact_assembly.hpp), so nothing here knows what kind of body is behind a contact.
#include <array>
#include <cstdint>
#include <memory>
#include <moreau/broadphase.hpp>
#include <moreau/detector.hpp>
#include <moreau/field_cache.hpp>
#include <moreau/integrator.hpp>
#include <moreau/law.hpp>
#include <moreau/shape.hpp>
#include <moreau/solver.hpp>
#include <moreau/step.hpp>
#include <string>
#include <vector>

#include "../plugin/owned.hpp"
#include "placement.hpp"
#include "problem_export.hpp"
#include "contact_assembly.hpp"
#include "shadow_solvers.hpp"
#include "solve_log.hpp"
#include "law_step.hpp"
#include "swept_detection.hpp"

namespace moreau::kernel {

struct Contactor {
  int body = -1;
  int group = -1;
  Owned<Shape> shape;
  Placement placement;  ///< in the frame of its node (rigid: the body frame, origin the centre of mass); identity for most
  int model = -1;       ///< its body's modelization (index into the models)
  std::size_t node = 0; ///< the node supporting it (row of its modelization's node set); a facet's first
  int count = 1;        ///< support nodes: 1, or a mesh facet's 2 to 4 (Shape::support() == facet)
  std::array<std::size_t, 4> nodes{};  ///< a facet's nodes, outward order (rows of the node set)
};

/// A detector for an ordered pair of shape names; `swap`: the detector's first shape is
/// the pair's second.
struct DetectorUse {
  std::string first, second;
  const Detector* detector = nullptr;
  bool swap = false;
};

class ContactStages {
 public:
  // Built by the scene builder.
  std::vector<Contactor> contactors;
  int groups = 0;
  std::vector<int> law_of;  ///< groups × groups → index into laws, −1: no interaction
  std::vector<Owned<Law>> laws;  ///< in the order of the scene's law names (the `law` field indexes them)
  std::vector<Owned<Detector>> detector_objects;
  std::vector<DetectorUse> detectors;
  Owned<BroadPhase> broadphase;
  Owned<Solver> solver;
  std::vector<ContactModel> models;  ///< every modelization of the scene with its integrator
  double alert = 0;
  bool stop_on_failure = false;
  std::unique_ptr<ProblemExport> exporter;  ///< null unless the scene has `export_problems`
  SolveLog solve_log;  ///< misses and worst error of the run's solves (its tolerance set by the builder)
  /// Null unless MOREAU_SHADOW_SOLVERS names solvers that solve every problem beside
  /// `solver` without changing the run (shadow_solvers.hpp).
  std::unique_ptr<ShadowSolvers> shadows;

  /// After the laws are made: their internal variables on the `contacts` set (law_step.hpp).
  void setup_laws(State& state, const std::vector<std::string>& names, const std::vector<std::string>& pointers) {
    law_step_.setup(state, laws, names, pointers);
  }

  void detection_configuration(StepContext& ctx);
  void broad_phase(StepContext& ctx);
  void narrow_phase(StepContext& ctx);
  void warm_start(StepContext& ctx);
  void solve(StepContext& ctx);
  void store_reactions(StepContext& ctx);

  long last_iterations() const { return report_.iterations; }
  double last_error() const { return report_.error; }
  /// Seconds (the stage clock's) spent building W — H and the modelizations' blocks of
  /// LHS⁻¹ — within the solve stage, over the run so far.
  double assembly_seconds() const { return assembly_seconds_; }
  /// μ of each contact in the last solve (rows of the `contacts` set), as its law chose it
  /// for that step (static or dynamic friction): what the analyses compare the forces with.
  const Eigen::VectorXd& last_friction() const { return problem_.mu; }
  /// The last step's local velocities, contact by contact (rows of the contacts set),
  /// normal first: H v⁻ and H v⁺ (= W r + q, the laws' shifts taken out), from each side's
  /// modelization (a mesh side: its nodes weighted at the point). Empty when the step had
  /// no contacts.
  const Eigen::VectorXd& local_velocity_begin() const { return u_begin_; }
  const Eigen::VectorXd& local_velocity_end() const { return u_; }
  /// After the solver is made: its own state (Solver::state_fields) as the `solver` set,
  /// one row, written with every frame and restored on restart.
  void setup_solver(State& state);
  /// A restart loaded the `contacts` set (keys and what persists) from its frame: the next
  /// warm start continues from it, and the start-of-run overlap warning is not given.
  /// `solver_state`: the frame also held the solver's state (the `solver` set), which the
  /// solver takes back; without it the solver starts as in a new run.
  void restored(State& state, bool solver_state);

 private:
  struct Detected {
    int contactor[2];
    ContactPoint point;
    int law;
    std::uint64_t key;
    bool swept = false;    ///< from swept detection (swept_detection.hpp)
    double start_gap = 0;  ///< gap at the start configuration, where known (else the point's gap)
  };
  const DetectorUse* detector_for(const std::string& a, const std::string& b) const;
  /// Numbers the contactors' shape names and finds the detector of each ordered pair of
  /// them once (narrow_phase), instead of comparing names for every pair of every step.
  void index_shape_kinds();
  /// The `contacts` set's fields warm_start() and store_reactions() write at every step,
  /// resolved once (moreau/field_cache.hpp) instead of by name (a map of strings each):
  /// with the integrator's such lookups they were a fifth of a one-body step's CPU (libc
  /// memcmp, block_on_incline_2d).
  struct ContactFieldRefs {
    FieldCacheKey cache_key;
    Field *key = nullptr, *bodies = nullptr, *point = nullptr, *normal = nullptr, *gap = nullptr, *law = nullptr,
          *impulse = nullptr, *force = nullptr, *normal_force = nullptr, *status = nullptr, *velocity = nullptr;
    static ContactFieldRefs of(EntitySet& set);  // throws, naming it, when the set lacks one
  };
  ContactFieldRefs contact_fields_;
  std::vector<int> shape_kind_;                     ///< per contactor: the index of its shape name
  std::vector<const DetectorUse*> kind_detector_;   ///< kinds × kinds: detector_for() of the two names
  std::size_t kinds_ = 0;
  /// Pose of contactor i for its detector (a facet's: its nodes).
  Pose pose_of(std::size_t i) const;
  /// Of the contacts between one contactor and the facets of one body, keeps the nearest.
  void keep_nearest_facets();
  /// Marks in `drop` the facet contacts at a corner (edge) of a facet that holds a nearer
  /// contact of the same candidate (keep_nearest_facets).
  void drop_corners_of_nearer_facets(std::vector<char>& drop) const;
  /// A facet contact inside its facet with the candidate in front of it (kept beside the nearest).
  bool inside_facet_in_front(const Detected& ct) const;
  /// The step's contacts as sides for the assembly (support nodes and weights).
  void fill_sides(int d);
  /// Writes the step's problem (export_problems), local or global.
  void export_problem(const StepContext& c, const Eigen::VectorXd& warm_start, const Eigen::VectorXd& solved);
  void warn_initial_overlaps(const StepContext& c);
  void warn_swept_rebound(const StepContext& c, const Detected& ct, double approach, double law_shift, double shift);
  bool swept_rebound_warned_ = false;
  std::string worst_contact_bodies(const State& st) const;
  bool initial_overlaps_checked_ = false;

  /// Per contactor: world pose at the detection configuration (position 3, then rotation
  /// 4: 2D angle in [0]) and distance it may travel in the step (its node's, plus the
  /// rotation of an offset contactor).
  std::vector<double> contactor_poses_, contactor_sweep_;
  /// Facet contactors: index into facet_points_ (12 values: up to 4 nodes × 3), else −1.
  std::vector<long> facet_index_;
  std::vector<double> facet_points_;
  BroadPhaseInput bp_;
  std::vector<std::pair<int, int>> pairs_;
  std::vector<Detected> contacts_;
  std::vector<ContactPoint> scratch_;
  ContactSides sides_;
  ContactAssembly assembly_;
  double assembly_seconds_ = 0;
  std::vector<double> start_gaps_;
  std::vector<double> swept_caps_;  ///< per contact, the largest normal shift (swept contacts)
  bool swept_caps(const StepContext& c);
  bool solver_state_ = false;  ///< the solver keeps state over solves (the `solver` set)
  SweptDetection swept_;
  LocalProblem problem_;
  Eigen::VectorXd r_, u_;
  SolverReport report_;
  std::vector<std::pair<std::uint64_t, std::ptrdiff_t>> previous_keys_;  ///< scratch of warm_start
  // The laws' part of the solve (law_step.hpp).
  void solve_with_laws(StepContext& c);
  /// New contacts of laws with internal variables continue a nearby vanished row of the
  /// same two contactors (a face contact whose points changed feature).
  void continue_nearby(const EntitySet& set, std::vector<std::ptrdiff_t>& from);
  LawStep law_step_;
  std::vector<char> new_contact_;     ///< per contact: no row of the previous step continues it
  std::vector<int> contact_law_;      ///< per contact: index into laws
  std::vector<double> contact_gap_;   ///< per contact: gap at the detection configuration
  Eigen::VectorXd q_free_, u_begin_;  ///< H v_free, H v⁻
  bool laws_warned_ = false;
};

}  // namespace moreau::kernel
