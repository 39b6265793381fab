#pragma once
// The contact stages of a step (DESIGN §1): detection configuration, broad phase, narrow
// phase, warm start, solve, store reactions. Built only for scenes with interactions.
#include <cstdint>
#include <memory>
#include <moreau/broadphase.hpp>
#include <moreau/detector.hpp>
#include <moreau/integrator.hpp>
#include <moreau/law.hpp>
#include <moreau/shape.hpp>
#include <moreau/solver.hpp>
#include <moreau/step.hpp>
#include <string>
#include <vector>

#include "../io/output_writer.hpp"
#include "../plugin/owned.hpp"
#include "placement.hpp"
#include "problem_export.hpp"
#include "rigid_assembly.hpp"

namespace moreau::kernel {

struct Contactor {
  int body = -1;
  int group = -1;
  Owned<Shape> shape;
  Placement placement;  ///< in the body frame (origin: centre of mass); identity for most
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
  std::vector<Owned<Law>> laws;
  std::vector<Owned<Detector>> detector_objects;
  std::vector<DetectorUse> detectors;
  Owned<BroadPhase> broadphase;
  Owned<Solver> solver;
  double alert = 0;
  bool stop_on_failure = false;
  std::unique_ptr<ProblemExport> exporter;  ///< null unless the scene has `export_problems`

  void detection_configuration(StepContext& ctx);
  void broad_phase(StepContext& ctx);
  void narrow_phase(StepContext& ctx);
  void warm_start(StepContext& ctx);
  void solve(StepContext& ctx, const Integrator& integrator);
  void store_reactions(StepContext& ctx);

  /// The contacts of the last step, for the output.
  io::ContactFrame frame(int dim, double h) const;
  long last_iterations() const { return report_.iterations; }
  double last_error() const { return report_.error; }
  /// Restores the warm start of a restart (keys: nc × 3, impulses: nc × d).
  void restore(const std::vector<int>& keys, const std::vector<double>& impulses, int dim);

 private:
  struct Detected {
    int contactor[2];
    ContactPoint point;
    int law;
    std::uint64_t key;
  };
  const DetectorUse* detector_for(const std::string& a, const std::string& b) const;
  void warn_initial_overlaps(const StepContext& c);
  bool initial_overlaps_checked_ = false;

  std::vector<double> poses_;  ///< per body: position (3) then rotation (4: 2D angle in [0])
  std::vector<double> sweep_;  ///< per body: distance it may travel in the step (m)
  /// Per contactor: world pose (same layout as poses_) and distance it may travel in the
  /// step (its body's sweep, plus the rotation of an offset contactor).
  std::vector<double> contactor_poses_, contactor_sweep_;
  BroadPhaseInput bp_;
  std::vector<std::pair<int, int>> pairs_;
  std::vector<Detected> contacts_;
  std::vector<ContactPoint> scratch_;
  RigidAssembly assembly_;
  LocalProblem problem_;
  Eigen::VectorXd r_, u_;
  SolverReport report_;
  // Warm start: previous step's keys (sorted) and local impulses.
  std::vector<std::pair<std::uint64_t, std::size_t>> previous_keys_;
  std::vector<double> previous_r_;
};

}  // namespace moreau::kernel
