#pragma once
// Wall time per stage over a run, printed as shares at the end. Only stages that did
// work are timed (and shown). With the environment variable MOREAU_STAGE_CLOCK=cpu the
// stages are timed in the CPU time of the running thread instead: on a shared machine a
// benchmark (scripts/bench_scenes.py) then measures the work of each stage, not the time
// other processes held the core.
#include <time.h>

#include <array>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <moreau/stage.hpp>
#include <ostream>

namespace moreau::kernel {

/// steady_clock, or the thread's CPU clock when MOREAU_STAGE_CLOCK=cpu (read once).
struct StageClock {
  using duration = std::chrono::nanoseconds;
  using rep = duration::rep;
  using period = duration::period;
  using time_point = std::chrono::time_point<StageClock>;
  static constexpr bool is_steady = true;
  static bool cpu() {
    static const bool on = [] {
      const char* v = std::getenv("MOREAU_STAGE_CLOCK");
      return v && std::strcmp(v, "cpu") == 0;
    }();
    return on;
  }
  static time_point now() {
    if (!cpu()) return time_point(std::chrono::duration_cast<duration>(std::chrono::steady_clock::now().time_since_epoch()));
    return thread_cpu();
  }
  /// The running thread's CPU clock, whatever MOREAU_STAGE_CLOCK says (shadow solvers).
  static time_point thread_cpu() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return time_point(duration(static_cast<rep>(t.tv_sec) * 1000000000 + t.tv_nsec));
  }
};

class StageTimer {
 public:
  using clock = StageClock;
  void add(Stage s, clock::duration d) {
    seconds_[static_cast<int>(s)] += std::chrono::duration<double>(d).count();
    active_[static_cast<int>(s)] = true;
  }
  void add_hooks(clock::duration d) { hooks_ += std::chrono::duration<double>(d).count(); }
  /// Part of the solve stage spent building W (H, the blocks of LHS⁻¹), printed under it.
  void set_solve_assembly(double seconds) { solve_assembly_ = seconds; }
  double solve_assembly() const { return solve_assembly_; }
  /// Part of the solve stage spent on shadow solvers (shadow_solvers.hpp): taken out of
  /// the stage, so that it is the scene solver's, and printed under it.
  void set_solve_shadows(double seconds) {
    seconds_[static_cast<int>(Stage::solve)] -= seconds - solve_shadows_;
    solve_shadows_ = seconds;
  }
  double seconds(Stage s) const { return seconds_[static_cast<int>(s)]; }
  bool active(Stage s) const { return active_[static_cast<int>(s)]; }
  double hooks() const { return hooks_; }
  double total() const {
    double t = hooks_;
    for (double s : seconds_) t += s;
    return t;
  }
  void print(std::ostream& os, long steps) const;

 private:
  std::array<double, stage_count> seconds_{};
  std::array<bool, stage_count> active_{};
  double hooks_ = 0;
  double solve_assembly_ = 0;
  double solve_shadows_ = 0;
};

}  // namespace moreau::kernel
