#pragma once
// The one adapter between the kernel's storage and what analyses see (AnalysisFrame,
// sdk/include/moreau/analysis.hpp). Everything an analysis reads of the bodies (mass,
// position, velocities at both depths, second moment of mass, external forces) and of
// the contacts (bodies, point, frame, impulse, status, μ, groups, relative velocities)
// is gathered here and nowhere else, so that a change in how the state or the contacts
// are stored is a change to this file only.
#include <moreau/analysis.hpp>
#include <string>
#include <vector>

namespace moreau::kernel {

struct World;

class FrameView {
 public:
  /// Reads what does not change over a run: volumes and bounding radii from the shapes,
  /// the contactor groups, which bodies are driven.
  explicit FrameView(const World& world);

  /// The frame after `steps_done` steps (stage output: end-of-step values in Depth::begin,
  /// start-of-step values in Depth::end), with that step's contacts (the `contacts` set);
  /// `after_step` false for a run's first frame, which follows no step (no contacts).
  /// The returned view stays valid until the next call.
  const AnalysisFrame& build(const World& world, long steps_done, bool after_step);

  const std::vector<std::string>& group_names() const { return group_names_; }
  const std::vector<std::string>& all_groups() const { return all_groups_; }

 private:
  void bodies(const World& world);
  void contacts(const World& world);
  /// Contact c's u⁻, u⁺ (local frame) from the step's H v when a side is not a rigid body;
  /// false for rigid pairs (their velocities give it).
  bool mesh_side_velocity(const World& world, std::size_t c, double* u_begin, double* u_end) const;

  AnalysisFrame frame_;
  // Constant over the run.
  std::vector<double> volume_, radius_;
  std::vector<char> driven_;
  std::vector<char> rigid_;               ///< bodies of the `rigid` modelization (one node each)
  std::vector<std::string> group_names_;  ///< interacting groups, by the contact stages' group index
  std::vector<std::string> all_groups_;   ///< every contactor group of the scene
  std::vector<int> contactor_group_;      ///< detected contactor → its group index
  // Per frame: the bodies' values gathered from their modelizations' node sets.
  std::vector<char> sample_;
  std::vector<double> mass_, x_, x0_, v_, v0_, w_, w0_, lever_, second_, force_, torque_;
  std::vector<int> contact_bodies_, contact_groups_;
  std::vector<signed char> status_;
  std::vector<double> frame_rows_, mu_, u_begin_, u_end_;
};

}  // namespace moreau::kernel
