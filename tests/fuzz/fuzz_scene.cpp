// Fuzz target: a scene as `moreau check` takes it — parsed by the kernel's JSON reader,
// validated, and built (plugins loaded and constructed), never run.
//
// Every input must end as a valid scene or as moreau's input errors (exit 2). Anything
// else is a finding: a signal, a sanitizer report, or another exception (what the command
// line prints as "internal error", exit 1), which the harness turns into an abort.
#include <dlfcn.h>

#include <cstdint>
#include <filesystem>
#include <cstdio>
#include <cstdlib>
#include <moreau/error.hpp>
#include <string>

#include "kernel/plugin/registry.hpp"
#include "kernel/scene/builder.hpp"
#include "kernel/scene/json_file.hpp"

// libFuzzer keeps the coverage counters of every instrumented library it saw, and reads
// them after each input: a plugin library unloaded when the World goes (as the kernel
// does) would leave it reading unmapped memory. So every plugin library is opened once
// here and never closed; the kernel's own loads then only add references.
extern "C" int LLVMFuzzerInitialize(int*, char***) {
  namespace fs = std::filesystem;
  const fs::path folder = moreau::kernel::Registry::installed_folder();
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(folder, ec))
    if (e.path().extension() == ".so") dlopen(e.path().c_str(), RTLD_NOW | RTLD_LOCAL | RTLD_NODELETE);
  return 0;
}

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
