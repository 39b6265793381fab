#include "registry.hpp"

#include "../text/did_you_mean.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <moreau/error.hpp>
#include <set>
#include <sstream>

#include "boundary.hpp"

namespace fs = std::filesystem;

namespace moreau::kernel {

namespace {

constexpr const char* kPrefix = "libmoreau_";
constexpr const char* kSuffix = ".so";

/// (kind, name) from a library file name, if it follows the naming convention.
bool parse_library_name(const std::string& file, std::string& kind, std::string& name) {
  const std::string prefix = kPrefix, suffix = kSuffix;
  if (file.size() <= prefix.size() + suffix.size() || file.rfind(prefix, 0) != 0 ||
      file.compare(file.size() - suffix.size(), suffix.size(), suffix) != 0)
    return false;
  const std::string core = file.substr(prefix.size(), file.size() - prefix.size() - suffix.size());
  const auto us = core.find('_');
  if (us == std::string::npos || us == 0 || us + 1 == core.size()) return false;
  kind = core.substr(0, us);
  name = core.substr(us + 1);
  return true;
}

class CollectingRegistrar : public Registrar {
 public:
  void add(Registration r) override { list.push_back(std::move(r)); }
  std::vector<Registration> list;
};

std::string join(const std::vector<std::string>& v, const char* sep = ", ") {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : sep) + x;
  return s;
}

}  // namespace

std::string plugin_label(Kind kind, const std::string& name, const std::string& pointer) {
  return std::string("the ") + kind_name(kind) + " '" + name + "'" + (pointer.empty() ? "" : " (" + pointer + ")");
}

Registry::Registry(std::vector<fs::path> search_paths) : paths_(std::move(search_paths)) {}

fs::path Registry::installed_folder() {
  std::error_code ec;
  fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (ec) return {};
  return exe.parent_path().parent_path() / MOREAU_PLUGIN_RELDIR;
}

std::vector<fs::path> Registry::standard_paths(const std::vector<std::string>& scene_paths, const fs::path& scene_dir) {
  std::vector<fs::path> out;
  for (const auto& p : scene_paths) {
    fs::path path(p);
    out.push_back(path.is_absolute() ? path : scene_dir / path);
  }
  if (const char* env = std::getenv("MOREAU_PLUGIN_PATH")) {
    std::stringstream ss(env);
    std::string item;
    static std::set<std::string> warned;  // once per folder, however many registries
    while (std::getline(ss, item, ':')) {
      if (item.empty()) continue;
      std::error_code ec;
      if (!fs::is_directory(item, ec) && warned.insert(item).second)
        std::fprintf(stderr, "warning: MOREAU_PLUGIN_PATH names \"%s\", which is not a folder: no plugin is looked for there\n",
                     item.c_str());
      out.emplace_back(item);
    }
  }
  if (auto inst = installed_folder(); !inst.empty()) out.push_back(inst);
  return out;
}

std::string Registry::library_file_name(Kind kind, const std::string& name) {
  return std::string(kPrefix) + kind_name(kind) + "_" + name + kSuffix;
}

fs::path Registry::locate(Kind kind, const std::string& name) const {
  const std::string file = library_file_name(kind, name);
  for (const auto& dir : paths_) {
    std::error_code ec;
    fs::path candidate = dir / file;
    if (fs::exists(candidate, ec)) return candidate;
  }
  return {};
}

void Registry::add_builtin(Registration r) {
  auto key = std::make_pair(r.kind, r.name);
  entries_[key] = RegistryEntry{nullptr, std::move(r)};
}

std::vector<std::pair<Kind, std::string>> Registry::load_library(const fs::path& file) {
  std::error_code ec;
  const std::string key = fs::weakly_canonical(file, ec).string();
  if (loaded_.count(key)) return {};
  LibraryHandle lib = LoadedLibrary::open(file);
  CollectingRegistrar collect;
  try {
    lib->manifest().register_all(collect);
  } catch (...) {
    try {
      rethrow_kernel_owned("the plugin library", "to register its plugins");
    } catch (const std::exception& e) {
      throw InputError("", e.what(), file.string());
    }
  }
  if (collect.list.empty())
    throw InputError("", "the plugin library registered nothing (its manifest is valid but it registers no plugin)",
                     file.string());
  std::vector<std::pair<Kind, std::string>> keys;
  // Check every registration before adding any, so a failed library leaves no trace.
  for (const auto& r : collect.list) {
    auto k = std::make_pair(r.kind, r.name);
    auto it = entries_.find(k);
    if (it != entries_.end()) {
      const std::string other = it->second.library ? it->second.library->path().string() : std::string("the kernel");
      throw InputError("",
                       std::string("duplicate plugin name: ") + kind_name(r.kind) + " '" + r.name +
                           "' is registered both by " + other + " and by " + file.string(),
                       file.string());
    }
    if (std::find(keys.begin(), keys.end(), k) != keys.end())
      throw InputError("", std::string("duplicate plugin name: ") + kind_name(r.kind) + " '" + r.name +
                               "' is registered twice by " + file.string(), file.string());
    keys.push_back(k);
  }
  for (auto& r : collect.list) {
    auto k = std::make_pair(r.kind, r.name);
    entries_[k] = RegistryEntry{lib, std::move(r)};
  }
  loaded_[key] = lib;
  return keys;
}

const RegistryEntry* Registry::find(Kind kind, const std::string& name) {
  auto k = std::make_pair(kind, name);
  if (auto it = entries_.find(k); it != entries_.end()) return &it->second;
  fs::path file = locate(kind, name);
  if (file.empty()) return nullptr;
  auto keys = load_library(file);
  if (auto it = entries_.find(k); it != entries_.end()) return &it->second;
  std::vector<std::string> got;
  for (const auto& [kk, nn] : keys) got.push_back(std::string(kind_name(kk)) + " '" + nn + "'");
  throw InputError("", std::string("the plugin library registered ") + join(got) + " but not " + kind_name(kind) +
                           " '" + name + "'", file.string());
}

const RegistryEntry& Registry::require(Kind kind, const std::string& name, const std::string& pointer) {
  const RegistryEntry* e = nullptr;
  try {
    e = find(kind, name);
  } catch (const InputError& err) {
    // Keep the library's file as the place of the fault, and say which scene key asked for it.
    throw InputError(pointer, err.what() + std::string(" (library ") + err.file() + ")");
  }
  if (e) return *e;
  auto names = available(kind);
  std::string paths;
  for (const auto& p : paths_) paths += (paths.empty() ? "" : ", ") + p.string();
  const std::string hint = did_you_mean(name, names, '\'');
  throw InputError(pointer, std::string("unknown ") + kind_name(kind) + " '" + name + "'" + hint +
                                (hint.empty() ? "; valid names: " : " Valid names: ") +
                                (names.empty() ? std::string("(none)") : join(names)) + " (looked for " +
                                library_file_name(kind, name) + " in: " + (paths.empty() ? "(no folder)" : paths) +
                                ")");
}

std::vector<std::string> Registry::available(Kind kind) const {
  std::set<std::string> names;
  for (const auto& [k, e] : entries_)
    if (k.first == kind) names.insert(k.second);
  for (const auto& dir : paths_) {
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) continue;
    for (const auto& ent : fs::directory_iterator(dir, ec)) {
      std::string kk, nn;
      if (parse_library_name(ent.path().filename().string(), kk, nn) && kk == kind_name(kind)) names.insert(nn);
    }
  }
  return {names.begin(), names.end()};
}

void Registry::load_all() {
  std::set<std::string> seen;
  for (const auto& dir : paths_) {
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) continue;
    std::vector<fs::path> files;
    for (const auto& ent : fs::directory_iterator(dir, ec)) files.push_back(ent.path());
    std::sort(files.begin(), files.end());
    for (const auto& f : files) {
      std::string kk, nn;
      const std::string fname = f.filename().string();
      if (!parse_library_name(fname, kk, nn) || seen.count(fname)) continue;
      seen.insert(fname);
      load_library(f);
    }
  }
}

std::vector<const RegistryEntry*> Registry::entries() const {
  std::vector<const RegistryEntry*> out;
  for (const auto& [k, e] : entries_) out.push_back(&e);
  return out;
}

}  // namespace moreau::kernel
