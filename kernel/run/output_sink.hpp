#pragma once
// The run's HDF5 output and restart, as the scheduler sees them (kernel/io does the
// file work).
#include <memory>
#include <optional>
#include <string>

#include "frame_sink.hpp"
#include "world.hpp"

namespace moreau::kernel {

/// Opens the output file for a new run, or, with `continue_after`, for a run restarted
/// from that step (frames after it are dropped when the file already holds the run).
/// An unwritable path is an InputError; nothing is created then.
std::unique_ptr<FrameSink> open_output(const World& world, const std::string& path,
                                       std::optional<long> continue_after = std::nullopt);

/// Loads the restart state of frame `frame` (default: the last complete one) of an
/// output file into the world's state; returns the frame's step.
long load_restart(World& world, const std::string& file, std::optional<long> frame);

}  // namespace moreau::kernel
