#pragma once
// Wall time per stage over a run, printed as shares at the end. Only stages that did
// work are timed (and shown).
#include <array>
#include <chrono>
#include <moreau/stage.hpp>
#include <ostream>

namespace moreau::kernel {

class StageTimer {
 public:
  using clock = std::chrono::steady_clock;
  void add(Stage s, clock::duration d) {
    seconds_[static_cast<int>(s)] += std::chrono::duration<double>(d).count();
    active_[static_cast<int>(s)] = true;
  }
  void add_hooks(clock::duration d) { hooks_ += std::chrono::duration<double>(d).count(); }
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
};

}  // namespace moreau::kernel
