#pragma once
// How a plugin library tells the kernel what it provides.
//
// A plugin class registers itself in its own .cpp file, next to its schema:
//
//     class Theta : public moreau::Integrator {
//      public:
//       static moreau::Schema schema();              // parameters it accepts
//       static constexpr const char* doc = "…";      // one line for `moreau plugins`
//       Theta(const moreau::Params&, const moreau::BuildContext&);
//       …
//     };
//     MOREAU_REGISTER(Theta, "theta")
//
// and the library declares itself once (in any one of its files):
//
//     MOREAU_PLUGIN_LIBRARY("moreau_integrator_theta")
//
// The kernel finds the library for (kind, name) by its file name,
// lib<prefix>_<kind>_<name>.so (see docs/plugins.md), reads its manifest, checks the ABI
// version and build identity, then calls the registration function.
#define BOOST_DLL_USE_STD_FS 1
#include <boost/dll/alias.hpp>
#include <cstdint>
#include <functional>
#include <memory>
#include <stdexcept>
#include <moreau/params.hpp>
#include <moreau/schema.hpp>
#include <moreau/version.hpp>
#include <string>
#include <vector>

/// Marks what the SDK exports from every library that includes it (plugins build with
/// hidden visibility): the plugin interfaces, so that their type identity is shared.
#define MOREAU_API __attribute__((visibility("default")))

namespace moreau {

/// Plugin kinds, one folder each under plugins/.
/// New kinds go at the end (the values are part of the plugin ABI, sdk/README.md).
enum class Kind { modelization, integrator, force, hook, shape, detector, broadphase, law, solver, writer, analysis, generator };
inline constexpr Kind all_kinds[] = {Kind::modelization, Kind::integrator, Kind::force,  Kind::hook,
                                     Kind::shape,        Kind::detector,   Kind::broadphase, Kind::law,
                                     Kind::solver,       Kind::writer,     Kind::analysis,   Kind::generator};
inline const char* kind_name(Kind k) {
  switch (k) {
    case Kind::modelization: return "modelization";
    case Kind::integrator: return "integrator";
    case Kind::force: return "force";
    case Kind::hook: return "hook";
    case Kind::shape: return "shape";
    case Kind::detector: return "detector";
    case Kind::broadphase: return "broadphase";
    case Kind::law: return "law";
    case Kind::solver: return "solver";
    case Kind::writer: return "writer";
    case Kind::analysis: return "analysis";
    case Kind::generator: return "generator";
  }
  return "?";
}

/// Base of every object a plugin creates. The kernel keeps the library loaded as long
/// as any such object lives.
class MOREAU_API Plugin {
 public:
  virtual ~Plugin() = default;
};

/// What a factory may know about the scene being built.
struct BuildContext {
  int dimension = 3;
  double time_step = 0;
  double theta = 0.5;      ///< θ of the θ-scheme (time.theta)
  std::string scene_file;  ///< path of the scene, for messages
  std::string scene_dir;   ///< folder of the scene (relative input paths resolve here)
  std::string output_dir;  ///< folder of the run's output file (relative output paths resolve here)
  /// Index of the body named `name`; throws InputError at `pointer` if there is none.
  std::function<int(const std::string& name, const std::string& pointer)> body_index;
  /// The state being built, when the plugin is created after the bodies (forces, hooks):
  /// a plugin addressing a body can check its modelization (`state->model_of(b)`) and
  /// fields (`state->has_node_field(b, name)`). Null for modelizations, shapes and laws.
  const class State* state = nullptr;
};

using Factory = std::function<std::unique_ptr<Plugin>(const Params&, const BuildContext&)>;

struct Registration {
  Kind kind;
  std::string name;
  std::string doc;
  Schema schema;
  Factory factory;
};

/// Receives a library's registrations (implemented by the kernel).
class MOREAU_API Registrar {
 public:
  virtual ~Registrar() = default;
  virtual void add(Registration r) = 0;
};

namespace detail {
/// The registrations of *this* library. Hidden visibility makes it one list per shared
/// library even though every library includes this header.
__attribute__((visibility("hidden"))) inline std::vector<Registration>& local_registrations() {
  static std::vector<Registration> list;
  return list;
}
/// What went wrong registering this library's plugins (a schema() that threw): static
/// constructors run inside the dynamic loader, where an exception cannot be caught and ends
/// the process, so AutoRegister keeps the message and register_all reports it to the kernel.
__attribute__((visibility("hidden"))) inline std::vector<std::string>& local_registration_errors() {
  static std::vector<std::string> list;
  return list;
}
template <class T>
struct AutoRegister {
  explicit AutoRegister(const char* name) noexcept {
    try {
      local_registrations().push_back(Registration{
          T::kind, name, T::doc, T::schema(),
          [](const Params& p, const BuildContext& c) -> std::unique_ptr<Plugin> { return std::make_unique<T>(p, c); }});
    } catch (const std::exception& e) {
      note(name, e.what());
    } catch (...) {
      note(name, "an exception that is not a std::exception");
    }
  }
  static void note(const char* name, const char* what) noexcept {
    try {
      local_registration_errors().push_back(std::string(kind_name(T::kind)) + " '" + name + "' threw: " + what);
    } catch (...) {
    }
  }
};
/// Called by register_all: the registrations that failed, as one error for the kernel.
inline void throw_registration_errors() {
  const auto& errors = local_registration_errors();
  if (errors.empty()) return;
  std::string s;
  for (std::size_t i = 0; i < errors.size(); ++i) s += (i ? "; " : "") + errors[i];
  throw std::runtime_error(s);
}
}  // namespace detail

}  // namespace moreau

/// C layout, read by the kernel before anything else in the library is trusted.
/// `abi_version` comes first and never moves, so any moreau can read it.
extern "C" struct moreau_manifest {
  std::uint32_t abi_version;
  const char* sdk_version;
  const char* build_id;
  const char* library_name;
  void (*register_all)(moreau::Registrar&);
};

#define MOREAU_CONCAT_(a, b) a##b
#define MOREAU_CONCAT(a, b) MOREAU_CONCAT_(a, b)

/// Registers plugin class CLASS under NAME, in the kind given by CLASS::kind.
#define MOREAU_REGISTER(CLASS, NAME) \
  static const ::moreau::detail::AutoRegister<CLASS> MOREAU_CONCAT(moreau_auto_register_, __COUNTER__){NAME};

/// The library's manifest and its exported entry point `moreau_plugin_manifest`.
#define MOREAU_PLUGIN_LIBRARY(LIBNAME)                                                       \
  namespace moreau_plugin_entry {                                                           \
  static void register_all(::moreau::Registrar& r) {                                        \
    ::moreau::detail::throw_registration_errors();                                           \
    for (auto& reg : ::moreau::detail::local_registrations()) r.add(reg);                    \
  }                                                                                          \
  static const moreau_manifest manifest{MOREAU_ABI_VERSION, MOREAU_SDK_VERSION, MOREAU_BUILD_ID, \
                                        LIBNAME, &register_all};                            \
  static const moreau_manifest* get_manifest() { return &manifest; }                       \
  }                                                                                          \
  BOOST_DLL_ALIAS(moreau_plugin_entry::get_manifest, moreau_plugin_manifest)
