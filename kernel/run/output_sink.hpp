#pragma once
// The run's HDF5 output and restart, as the scheduler sees them (kernel/io does the
// file work).
#include <memory>
#include <optional>
#include <string>

#include "frame_sink.hpp"
#include "world.hpp"

namespace moreau::kernel {

/// Creates the output file of a run, or, with `continue_after`, reopens the run's own
/// file to continue it after that step (its later frames are dropped). An unwritable
/// path is an InputError; nothing is created then.
std::unique_ptr<FrameSink> open_output(const World& world, const std::string& path,
                                       std::optional<long> continue_after = std::nullopt);

/// A restart into a new file: creates `path` with frame `step` of output file `source` as
/// its first frame, copied as it is (`copied`; false when `source` is of an earlier format:
/// the run must then write that frame itself).
std::unique_ptr<FrameSink> open_output_from(const World& world, const std::string& path, const std::string& source,
                                            long step, bool& copied);

/// Loads the restart state of frame `frame` (default: the last complete one) of an
/// output file into the world's state; returns the frame's step.
long load_restart(World& world, const std::string& file, std::optional<long> frame);

}  // namespace moreau::kernel
