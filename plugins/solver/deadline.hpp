#pragma once
// A wall-clock limit for one stage of a solver (used by `auto`, which shares time between
// its member methods): 0 seconds means none. Checked once per iteration.
#include <chrono>

namespace moreau {

class Deadline {
 public:
  explicit Deadline(double seconds)
      : none_(!(seconds > 0)),
        end_(std::chrono::steady_clock::now() +
             std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(none_ ? 0.0 : seconds))) {}
  bool passed() const { return !none_ && std::chrono::steady_clock::now() >= end_; }

 private:
  bool none_;
  std::chrono::steady_clock::time_point end_;
};

}  // namespace moreau
