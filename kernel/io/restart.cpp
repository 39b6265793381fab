#include "restart.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <moreau/error.hpp>

#include "field_io.hpp"
#include "h5.hpp"
#include "output_writer.hpp"
#include "restart_check.hpp"

namespace moreau::io {

namespace {

h5::Id open_output(const std::string& path) {
  h5::quiet();
  h5::Id f = h5::file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT));
  if (!f) throw InputError("", "cannot open as an HDF5 output file", path);
  std::string format;
  try {
    format = h5::read_attribute_string(f.get(), "format", path, "/");
  } catch (const InputError&) {
    throw InputError("/", "not a moreau output file (no \"format\" attribute)", path);
  }
  if (format != output_format && format != output_format_v1)
    throw InputError("/", "unsupported output format \"" + format + "\" (expected " + output_format + " or " +
                              output_format_v1 + ")", path);
  return f;
}

std::vector<long> frames_of(hid_t file, const std::string& path) {
  std::vector<long> steps;
  if (!h5::exists(file, "/frames")) return steps;
  h5::Id g = h5::group(H5Gopen2(file, "/frames", H5P_DEFAULT));
  if (!g) throw InputError("/frames", "expected a group of frames", path);
  for (const auto& n : h5::children(g.get())) {
    const std::optional<long> step = frame_step(n);
    if (!step) throw InputError("/frames/" + n, "not a frame (frames are named by their step, 8 digits)", path);
    steps.push_back(*step);
  }
  std::sort(steps.begin(), steps.end());
  return steps;
}

/// Whether frame `fp` holds every field of the `solver` set (files before it have none).
bool solver_state_in(hid_t file, const std::string& fp, const State& state) {
  const EntitySet* set = state.find_set(sets::solver);
  if (!set) return false;
  for (const auto& field : set->fields())
    if (!h5::exists(file, fp + "/" + sets::solver + "/" + field.name())) return false;
  return true;
}

}  // namespace

std::vector<long> list_frames(const std::string& path) {
  h5::Id f = open_output(path);
  return frames_of(f.get(), path);
}

RestartFrame read_restart(const std::string& path, std::optional<long> step, State& state) {
  h5::Id f = open_output(path);
  const auto names = h5::read_strings(f.get(), "/bodies/name", path);
  if (names != state.names())
    throw InputError("/bodies/name", "the file holds " + std::to_string(names.size()) +
                                         " bodies that do not match the scene's " + std::to_string(state.bodies()),
                     path);
  const auto steps = frames_of(f.get(), path);
  if (steps.empty()) throw InputError("/frames", "the file has no complete frame to restart from", path);
  const long chosen = step ? *step : steps.back();
  if (!std::binary_search(steps.begin(), steps.end(), chosen))
    throw InputError("/frames", "no frame for step " + std::to_string(chosen) + "; the file has " +
                                    std::to_string(steps.size()) + " frames, steps " + std::to_string(steps.front()) +
                                    " to " + std::to_string(steps.back()),
                     path);
  const std::string fp = "/frames/" + frame_name(chosen);
  RestartFrame r;
  r.step = chosen;
  {
    h5::Id g = h5::group(H5Gopen2(f.get(), fp.c_str(), H5P_DEFAULT));
    if (!g) throw InputError(fp, "cannot open the frame (a group expected)", path);
    r.time = h5::read_attribute_double(g.get(), "time", path, fp);
    if (!std::isfinite(r.time)) throw InputError(fp, "attribute 'time' is not finite", path);
  }
  // The modelizations must be the scene's (a moreau-output/1 file has rigid bodies only).
  std::vector<std::string> models;
  for (const auto& m : state.models()) models.push_back(m.name);
  const std::vector<std::string> file_models =
      h5::exists(f.get(), "/models/name") ? h5::read_strings(f.get(), "/models/name", path) : std::vector<std::string>{"rigid"};
  if (file_models != models)
    throw InputError("/models/name", "the file's modelizations do not match the scene's", path);
  const std::string legacy = legacy_node_set(state);
  // Without the previous step's impulses the solver would start cold and end elsewhere
  // within its tolerance: the continuation would not be bit-identical. The contacts set
  // takes the frame's rows.
  if (EntitySet* contacts = state.find_set(sets::contacts)) {
    const std::string kp = fp + "/" + sets::contacts + "/key";
    const auto dims = h5::dimensions(f.get(), kp);
    contacts->rebuild(std::vector<std::ptrdiff_t>(dims.empty() ? 0 : dims[0], -1));
  }
  r.solver_state = solver_state_in(f.get(), fp, state);
  for (auto& set : state.sets()) {
    if (set.name() == sets::contacts && set.rows() == 0) continue;
    if (set.name() == sets::solver && !r.solver_state) continue;  // an older file: the solver starts anew
    for (auto& field : set.fields()) {
      const bool frame = field.spec().output == FieldOutput::frame;
      if (!field.spec().restart && !(frame && set.name() == sets::contacts)) continue;
      std::string dp = fp + "/" + set.name() + "/" + field.name();
      if (!h5::exists(f.get(), dp) && set.name() == legacy) dp = fp + "/" + field.name();  // moreau-output/1
      if (!field.spec().restart && !h5::exists(f.get(), dp)) continue;  // shown, not needed
      if (set.name() == sets::contacts && field.spec().depths == 2 && !h5::exists(f.get(), dp))
        throw InputError(dp, "missing: the scene's contact laws keep '" + field.name() +
                                 "' per contact and a continuation needs it (docs/laws.md); expected the output of a run "
                                 "with the same laws",
                         path);
      read_field(f.get(), dp, field, path);
      check_restart_field(field, dp, path);
    }
  }
  return r;
}

}  // namespace moreau::io
