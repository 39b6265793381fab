#pragma once
// Restart: the dynamic state (every field marked `restart`) read back bit-exactly from a
// frame of an output file.
#include <moreau/state.hpp>
#include <optional>
#include <string>
#include <vector>

namespace moreau::io {

struct RestartFrame {
  long step = 0;
  double time = 0;
  /// The frame's contacts (empty when it has none): nc × 3 identities (contactor,
  /// contactor, feature) and nc × d local impulses, the warm start of the next step.
  std::vector<int> contact_keys;
  std::vector<double> contact_impulses;
};

/// Steps of the complete frames in an output file, ascending.
std::vector<long> list_frames(const std::string& path);

/// Loads frame `step` (default: the last) into `state` (both depths), and returns its
/// contacts for the warm start. The file must hold the same bodies. Faults: InputError with the file and the HDF5 path.
RestartFrame read_restart(const std::string& path, std::optional<long> step, State& state);

}  // namespace moreau::io
