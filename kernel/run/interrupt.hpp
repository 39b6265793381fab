#pragma once
// Ctrl-C (SIGINT) and SIGTERM during `moreau run`: the first one asks the run to stop
// after the step under way; the scheduler then writes that step's frame and closes the
// output as at a normal end (one self-contained file), and `moreau run` says how to
// continue with --restart. A second signal ends the process at once (the default action:
// the output then reads with its frames folder, docs/output.md).
#include <atomic>

namespace moreau::kernel {

class InterruptHandler {
 public:
  /// Installs the handlers (SIGINT, SIGTERM); the destructor restores the previous ones.
  InterruptHandler();
  ~InterruptHandler();
  InterruptHandler(const InterruptHandler&) = delete;
  InterruptHandler& operator=(const InterruptHandler&) = delete;

  /// The signal received (0: none yet), read by the scheduler after each step.
  static const std::atomic<int>& signal();
};

}  // namespace moreau::kernel
