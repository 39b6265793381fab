#include "restart.hpp"

#include <algorithm>
#include <moreau/error.hpp>

#include "h5.hpp"
#include "output_writer.hpp"

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
  if (format != "moreau-output/1")
    throw InputError("/", "unsupported output format \"" + format + "\" (expected moreau-output/1)", path);
  return f;
}

std::vector<long> frames_of(hid_t file) {
  std::vector<long> steps;
  if (!h5::exists(file, "/frames")) return steps;
  h5::Id g = h5::group(H5Gopen2(file, "/frames", H5P_DEFAULT));
  for (const auto& n : h5::children(g.get())) steps.push_back(std::stol(n));
  std::sort(steps.begin(), steps.end());
  return steps;
}

}  // namespace

std::vector<long> list_frames(const std::string& path) {
  h5::Id f = open_output(path);
  return frames_of(f.get());
}

RestartFrame read_restart(const std::string& path, std::optional<long> step, State& state) {
  h5::Id f = open_output(path);
  const auto names = h5::read_strings(f.get(), "/bodies/name", path);
  if (names != state.names())
    throw InputError("/bodies/name", "the file holds " + std::to_string(names.size()) +
                                         " bodies that do not match the scene's " + std::to_string(state.bodies()),
                     path);
  const auto steps = frames_of(f.get());
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
    r.time = h5::read_attribute_double(g.get(), "time", path, fp);
  }
  for (auto& field : state.fields()) {
    if (!field.spec().restart) continue;
    const std::string dp = fp + "/" + field.name();
    auto v = h5::read_doubles(f.get(), dp, nullptr, path);
    if (v.size() != field.bodies() * field.components())
      throw InputError(dp, "expected " + std::to_string(field.bodies() * field.components()) + " values, found " +
                               std::to_string(v.size()), path);
    for (int d = 0; d < field.spec().depths; ++d) std::copy(v.begin(), v.end(), field.data(static_cast<Depth>(d)));
  }
  // Without the previous step's impulses the solver would start cold and end elsewhere
  // within its tolerance: the continuation would not be bit-identical.
  const std::string kp = fp + "/contacts/key", ip = fp + "/contacts/impulse";
  if (h5::exists(f.get(), kp)) {
    std::vector<hsize_t> ks, is;
    const auto keys = h5::read_doubles(f.get(), kp, &ks, path);
    r.contact_impulses = h5::read_doubles(f.get(), ip, &is, path);
    const std::size_t nc = ks.empty() ? 0 : ks[0];
    if (ks.size() != 2 || ks[1] != 3) throw InputError(kp, "expected an nc × 3 dataset", path);
    if (is.size() != 2 || is[0] != nc || static_cast<int>(is[1]) != state.dimension())
      throw InputError(ip, "expected " + std::to_string(nc) + " × " + std::to_string(state.dimension()) + " impulses", path);
    r.contact_keys.assign(keys.begin(), keys.end());
  }
  return r;
}

}  // namespace moreau::io
