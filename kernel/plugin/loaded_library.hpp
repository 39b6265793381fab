#pragma once
// One plugin shared library, loaded and checked (manifest read, ABI and build identity
// compared) before anything else in it is called.
#include <filesystem>
#include <memory>
#include <string>

#include "owned.hpp"

struct moreau_manifest;

namespace moreau::kernel {

class LoadedLibrary {
 public:
  /// Loads `path` and checks its manifest. Throws InputError (file = path) with a
  /// distinct message for: cannot be loaded (the loader's own message), no manifest,
  /// ABI version mismatch, build identity mismatch.
  static LibraryHandle open(const std::filesystem::path& path);
  ~LoadedLibrary();

  const std::filesystem::path& path() const { return path_; }
  const moreau_manifest& manifest() const { return *manifest_; }

 private:
  struct Impl;
  LoadedLibrary(std::filesystem::path path, std::unique_ptr<Impl> impl, const moreau_manifest* m);
  std::filesystem::path path_;
  std::unique_ptr<Impl> impl_;
  const moreau_manifest* manifest_;
};

}  // namespace moreau::kernel
