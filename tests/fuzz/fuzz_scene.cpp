// Fuzz target: a scene as `moreau check` takes it — parsed by the kernel's JSON reader,
// validated, and built (plugins loaded and constructed), never run.
//
// Every input must end as a valid scene or as moreau's input errors (exit 2). Anything
// else is a finding: a signal, a sanitizer report, or another exception (what the command
// line prints as "internal error", exit 1), which the harness turns into an abort.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <moreau/error.hpp>
#include <string>

#include "kernel/scene/builder.hpp"
#include "kernel/scene/json_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    moreau::kernel::JsonFile file{"fuzz.json", text, moreau::kernel::parse_json(text, "fuzz.json")};
    moreau::kernel::check_scene(file);
  } catch (const moreau::InputErrors&) {
  } catch (const moreau::InputError&) {
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fuzz_scene: not an input error: %s\n", e.what());
    std::abort();
  } catch (...) {
    std::fprintf(stderr, "fuzz_scene: an exception that is not a std::exception\n");
    std::abort();
  }
  return 0;
}
