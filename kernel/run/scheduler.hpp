#pragma once
// The step scheduler: runs the stage sequence of DESIGN §1 for each step, with the
// hooks before and after each stage. Stages with no work are not called at all (and
// not timed), so a scene pays only for what it uses.
#include <array>
#include <atomic>
#include <functional>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "frame_sink.hpp"
#include "stage_timer.hpp"
#include "world.hpp"

namespace moreau::kernel {

struct RunOptions {
  long first_step = 0;               ///< completed steps at start (0, or the restart frame)
  std::optional<long> steps;         ///< how many steps to run (default: to the scene's duration)
  FrameSink* sink = nullptr;         ///< nullptr: no output
  bool write_first_frame = true;     ///< false when continuing a file that has it already
  std::ostream* progress = nullptr;  ///< nullptr: silent
  bool progress_terminal = false;
  /// Non-zero asks the run to stop after the step under way, whose frame is then written
  /// (InterruptHandler::signal(): Ctrl-C). nullptr: never.
  const std::atomic<int>* interrupt = nullptr;
};

struct RunSummary {
  long first_step = 0;
  long last_step = 0;  ///< completed steps at the end
  bool stopped_by_hook = false;
  std::string stop_reason;
  int interrupted_by = 0;  ///< the signal that stopped the run (0: none)
  StageTimer timer;
};

class Scheduler {
 public:
  explicit Scheduler(World& world);
  RunSummary run(const RunOptions& options);

 private:
  using StageFn = std::function<void(StepContext&)>;
  void build_stages();
  void apply_drivers(StepContext& ctx);
  void check_finite(long step) const;
  std::string stage_owner(Stage s) const;
  /// Fields the modelizations derive from their unknowns (stresses) are computed when they
  /// are read — a frame written, a hook looking at the state — not at every step: the
  /// update marks them stale, and this computes them from the step's ⁺ values (at
  /// Depth::end until end_step swaps the depths, at Depth::begin after).
  void refresh_derived_fields();

  bool derived_stale_ = false;
  Depth derived_depth_ = Depth::begin;

  World& w_;
  std::array<StageFn, stage_count> stages_;
  std::array<std::array<std::vector<const Owned<Hook>*>, 2>, stage_count> hooks_;
};

}  // namespace moreau::kernel
