#include "output_sink.hpp"

#include <moreau/error.hpp>

namespace moreau::kernel {

std::unique_ptr<FrameSink> open_output(const World&, const std::string&, std::optional<long>) {
  throw RunError("output: not wired yet");
}

long load_restart(World&, const std::string&, std::optional<long>) { throw RunError("restart: not wired yet"); }

}  // namespace moreau::kernel
