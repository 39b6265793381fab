// `moreau generate SCENE --out FULL.json`: runs the scene's generators and writes the scene
// with the generated bodies listed in `bodies` and no `generators`, so that a run is
// reproducible without them (same bodies, bit for bit: numbers are written so that they
// read back exactly).
#include <filesystem>
#include <fstream>
#include <ostream>

#include "../scene/builder.hpp"
#include "../scene/generate.hpp"
#include "commands.hpp"

namespace moreau::kernel {

int command_generate(const std::string& scene, const std::string& out_path, std::ostream& out, std::ostream& err) {
  return guarded(err, [&] {
    JsonFile file = read_json_file(scene);
    const std::size_t before = file.value.is_object() && file.value.contains("bodies") && file.value["bodies"].is_array()
                                   ? file.value["bodies"].size()
                                   : 0;
    const Generated generated = expand_generators(file);
    // The written scene must run: validate and build it as `moreau check` would, naming
    // the generator of a faulty generated body.
    generated.locate([&] {
      check_scene(file);
      return 0;
    });
    namespace fs = std::filesystem;
    const fs::path target(out_path);
    std::error_code ec;
    const fs::path parent = fs::absolute(target, ec).parent_path();
    if (!fs::is_directory(parent, ec))
      throw InputError("", "cannot write the scene: its folder " + parent.string() + " does not exist", out_path);
    const std::string part = out_path + ".part";
    {
      std::ofstream f(part, std::ios::binary | std::ios::trunc);
      if (!f) throw InputError("", "cannot write the scene (folder not writable)", out_path);
      f << file.value.dump(1) << "\n";
      f.close();
      if (!f) {
        fs::remove(part, ec);
        throw RunError("cannot finish writing " + part);
      }
    }
    fs::rename(part, target, ec);
    if (ec) {
      fs::remove(part, ec);
      throw RunError("cannot rename " + part + " to " + out_path);
    }
    const std::size_t after = file.value["bodies"].size();
    out << "wrote " << fs::absolute(target).string() << " (" << after << " bodies, " << after - before
        << " generated)\n";
    return 0;
  });
}

}  // namespace moreau::kernel
