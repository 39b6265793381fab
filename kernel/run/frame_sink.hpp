#pragma once
// Where the run's frames go (the HDF5 output writer, or nothing).
#include <moreau/state.hpp>
#include <vector>

#include "../io/output_writer.hpp"

namespace moreau::kernel {

struct SolverInfo {
  long iterations = 0;
  double error = 0;
};

class FrameSink {
 public:
  virtual ~FrameSink() = default;
  /// The state after `step` completed steps (time = step·h), end-of-step values in
  /// Depth::begin (depths were swapped at end_step). `extra`: groups the analyses add.
  virtual void write_frame(long step, double time, const State& state, const SolverInfo& solver,
                           const std::vector<io::FrameGroup>& extra = {}) = 0;
  /// The run ended normally: finalise (the file is valid before this too).
  virtual void close() = 0;
};

}  // namespace moreau::kernel
