// The plain driver of a fuzz target, for builds without libFuzzer (g++): runs the target
// once on each file given, or on every file of each folder given, and reports how many.
//   moreau_fuzz_<target>_replay FILE|FOLDER...
//   moreau_fuzz_<target>_replay --decode INPUT OUT.h5   (HDF5 targets: the file an input describes)
// A finding aborts (exit by SIGABRT) after the target printed what it found; the file
// being run is printed first, so the failing input is named.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#ifdef MOREAU_FUZZ_HDF5
#include "h5_records.hpp"
#endif

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);
// Optional, as in libFuzzer: a target that defines it is set up by it first.
extern "C" __attribute__((weak)) int LLVMFuzzerInitialize(int* argc, char*** argv);

namespace fs = std::filesystem;

static std::vector<std::uint8_t> slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

int main(int argc, char** argv) {
#ifdef MOREAU_FUZZ_HDF5
  if (argc == 4 && std::strcmp(argv[1], "--decode") == 0) {
    const auto bytes = slurp(argv[2]);
    // The restart target's first byte chooses its scene: skipped here like there.
    const std::size_t skip = MOREAU_FUZZ_SKIP;
    const bool ok = bytes.size() >= skip && moreau_fuzz::write_records(bytes.data() + skip, bytes.size() - skip, argv[3]);
    return ok ? 0 : 1;
  }
#endif
  if (LLVMFuzzerInitialize) LLVMFuzzerInitialize(&argc, &argv);
  std::vector<fs::path> files;
  for (int i = 1; i < argc; ++i) {
    std::error_code ec;
    if (fs::is_directory(argv[i], ec)) {
      std::vector<fs::path> in;
      for (const auto& e : fs::recursive_directory_iterator(argv[i]))
        if (e.is_regular_file()) in.push_back(e.path());
      std::sort(in.begin(), in.end());
      files.insert(files.end(), in.begin(), in.end());
    } else {
      files.emplace_back(argv[i]);
    }
  }
  for (const auto& f : files) {
    std::fprintf(stderr, "replaying %s\n", f.c_str());
    const auto bytes = slurp(f);
    LLVMFuzzerTestOneInput(bytes.data(), bytes.size());
  }
  std::printf("%zu inputs replayed, no finding\n", files.size());
  return 0;
}
