#pragma once
// The plugin registry: (kind, name) → registration, and the library it came from.
//
// Libraries are found by file name, lib moreau_<kind>_<name>.so, in the search paths in
// order (DESIGN §3.4: the scene's plugin_paths, then MOREAU_PLUGIN_PATH, then the
// installed plugin folder); the first match wins. Only the libraries a scene names are
// ever loaded; `load_all()` (for `moreau plugins`) loads every library in the paths.
#include <filesystem>
#include <map>
#include <moreau/plugin.hpp>
#include <string>
#include <utility>
#include <vector>

#include "boundary.hpp"
#include "loaded_library.hpp"
#include "owned.hpp"

namespace moreau::kernel {

/// "the hook 'energy_log' (/hooks/0)": a plugin as messages name it.
std::string plugin_label(Kind kind, const std::string& name, const std::string& pointer = "");

struct RegistryEntry {
  LibraryHandle library;  // null for kernel built-ins; declared first so it is released last
  Registration registration;  // its factory and schema are code and data of the library
};

class Registry {
 public:
  explicit Registry(std::vector<std::filesystem::path> search_paths);

  /// The standard search paths: `scene_paths` (relative ones resolved against
  /// `scene_dir`), then each folder of MOREAU_PLUGIN_PATH, then the installed folder.
  static std::vector<std::filesystem::path> standard_paths(const std::vector<std::string>& scene_paths,
                                                           const std::filesystem::path& scene_dir);
  /// The plugin folder of the running executable's prefix (<prefix>/<libdir>/moreau/plugins).
  static std::filesystem::path installed_folder();
  /// File name of the library providing (kind, name).
  static std::string library_file_name(Kind kind, const std::string& name);

  const std::vector<std::filesystem::path>& search_paths() const { return paths_; }

  /// The registration of (kind, name), loading its library if needed. Unknown name:
  /// InputError at `pointer` listing the valid names of that kind.
  const RegistryEntry& require(Kind kind, const std::string& name, const std::string& pointer = "");
  /// Same, but nullptr when no library provides it (other load errors still throw).
  const RegistryEntry* find(Kind kind, const std::string& name);

  /// Creates a plugin object whose class derives from T (T::kind must match). Whatever
  /// the plugin's constructor throws comes out kernel-owned (boundary.hpp): an InputError
  /// keeps its text and pointer; anything else is an InputError at `pointer` naming the
  /// plugin (a constructor's job is to check its parameters).
  template <class T>
  Owned<T> create(const std::string& name, const Params& params, const BuildContext& ctx,
                  const std::string& pointer = "") {
    const RegistryEntry& e = require(T::kind, name, pointer);
    std::unique_ptr<Plugin> obj;
    try {
      obj = e.registration.factory(params, ctx);
    } catch (...) {
      rethrow_kernel_owned_input(pointer, plugin_label(T::kind, name), "while it was being created");
    }
    auto* typed = dynamic_cast<T*>(obj.get());
    if (typed == nullptr)
      throw InputError(pointer, std::string("plugin '") + name + "' does not implement the " + kind_name(T::kind) +
                                    " interface");
    obj.release();
    return Owned<T>(e.library, std::unique_ptr<T>(typed), plugin_label(T::kind, name, pointer));
  }

  /// Loads one library file and registers what it provides. Returns its registrations'
  /// keys. Errors: see LoadedLibrary::open, plus "registered nothing" and duplicates.
  std::vector<std::pair<Kind, std::string>> load_library(const std::filesystem::path& file);
  /// Loads every plugin library in the search paths (first of each file name wins).
  void load_all();

  /// Names available for a kind: registered ones and library files in the paths.
  std::vector<std::string> available(Kind kind) const;
  /// Every registration, sorted by kind then name.
  std::vector<const RegistryEntry*> entries() const;

  /// Registers a kernel built-in (no library).
  void add_builtin(Registration r);

 private:
  std::filesystem::path locate(Kind kind, const std::string& name) const;
  std::vector<std::filesystem::path> paths_;
  std::map<std::pair<Kind, std::string>, RegistryEntry> entries_;
  std::map<std::string, LibraryHandle> loaded_;  // by canonical path
};

}  // namespace moreau::kernel
