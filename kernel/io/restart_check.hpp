#pragma once
// A restart frame checked whole before the run starts: a damaged or edited output file
// is refused at once (exit 2, naming the dataset) instead of failing mid-run or, worse,
// running on garbage (a NaN orientation, contact identities naming contactors that do
// not exist).
#include <moreau/state.hpp>
#include <string>

#include "restart.hpp"

namespace moreau::io {

/// A field just read from dataset `path` of `file` (read_restart): every value finite,
/// and an orientation field's rows unit quaternions (a run keeps them so to rounding).
void check_restart_field(const Field& field, const std::string& path, const std::string& file);

/// The frame's contacts (the `contacts` set as read_restart left it): identities are
/// integers naming contactors of the scene (`contactors`: its count of detected
/// contactors; 0: the scene has no interactions and ignores the frame's contacts).
/// Throws InputError with the file and the HDF5 path of the first fault.
void check_restart(const std::string& file, const RestartFrame& frame, const State& state, std::size_t contactors);

}  // namespace moreau::io
