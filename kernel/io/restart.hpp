#pragma once
// Restart: the dynamic state (every field marked `restart`, on every set) read back
// bit-exactly from a frame of an output file (moreau-output/2, or /1 for rigid-only
// scenes). The `contacts` set gets the frame's rows: its keys and what persists (the warm
// start), and its other frame fields when the file has them. The `solver` set (a solver's
// own state) gets the frame's values when it has all of them.
#include <moreau/state.hpp>
#include <optional>
#include <string>
#include <vector>

namespace moreau::io {

struct RestartFrame {
  long step = 0;
  double time = 0;
  /// The frame held every field of the `solver` set (a solver's own state); false also for
  /// files written before it or by a run whose solver kept none: the set is left zero.
  bool solver_state = false;
};

/// Steps of the complete frames in an output file, ascending.
std::vector<long> list_frames(const std::string& path);

/// Loads frame `step` (default: the last) into `state` (both depths of every restart
/// field; the contacts set's rows). The file must hold the same bodies and modelizations.
/// Faults: InputError with the file and the HDF5 path.
RestartFrame read_restart(const std::string& path, std::optional<long> step, State& state);

}  // namespace moreau::io
