// Fuzz target: an output file as `moreau run --restart FILE` reads it — the restart
// frame read and checked whole (read_restart, check_restart) and the warm start restored,
// then the file reopened to be continued in place (OutputWriter::append, the
// `--restart FILE --out FILE` path) and closed again.
//
// The first input byte chooses the scene the file must belong to (configs/
// block_on_incline_2d.json or configs/box_tower_3d.json, both with contacts); the rest is
// a list of HDF5 objects (h5_records.hpp). Every input must end as a restart that loads,
// leaving a finite state, or as an InputError naming the file. Anything else aborts.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <moreau/error.hpp>
#include <string>

#include "h5_records.hpp"
#include "kernel/run/output_sink.hpp"
#include "kernel/scene/builder.hpp"

namespace {

using moreau::kernel::World;

[[noreturn]] void finding(const std::string& what) {
  std::fprintf(stderr, "fuzz_restart: %s\n", what.c_str());
  std::abort();
}

World& world(int which) {
  static std::unique_ptr<World> worlds[2];
  static const char* scenes[2] = {MOREAU_SOURCE_DIR "/configs/block_on_incline_2d.json",
                                  MOREAU_SOURCE_DIR "/configs/box_tower_3d.json"};
  if (!worlds[which]) worlds[which] = moreau::kernel::build_world(scenes[which], moreau_fuzz::scratch_file("out.h5"));
  return *worlds[which];
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  World& w = world(data[0] % 2);
  static const std::string path = moreau_fuzz::scratch_file("restart.h5");
  if (!moreau_fuzz::write_records(data + 1, size - 1, path)) finding("cannot write the input file");
  try {
    const long step = moreau::kernel::load_restart(w, path, std::nullopt);
    for (const auto& set : w.state.sets())
      for (const auto& f : set.fields()) {
        if (!f.spec().restart) continue;
        for (std::size_t i = 0; i < f.rows() * static_cast<std::size_t>(f.components()); ++i)
          if (!std::isfinite(f.data(moreau::Depth::begin)[i]))
            finding("a restart left field '" + set.name() + "/" + f.name() + "' non-finite");
      }
    auto sink = moreau::kernel::open_output(w, path, step);
    sink->close();
  } catch (const moreau::InputError& e) {
    if (e.file() != path) finding("an input error that does not name the file: " + e.describe());
  } catch (const std::exception& e) {
    finding(std::string("not an input error: ") + e.what());
  } catch (...) {
    finding("an exception that is not a std::exception");
  }
  return 0;
}
