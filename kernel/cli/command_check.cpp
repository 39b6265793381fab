#include <ostream>

#include "../scene/builder.hpp"
#include "commands.hpp"

namespace moreau::kernel {

int command_check(const std::string& scene, std::ostream& out, std::ostream& err) {
  return guarded(err, [&] {
    check_scene(scene);
    out << scene << ": valid scene\n";
    return 0;
  });
}

}  // namespace moreau::kernel
