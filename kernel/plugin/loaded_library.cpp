#include "loaded_library.hpp"

#include <boost/dll/shared_library.hpp>
#include <moreau/error.hpp>
#include <moreau/plugin.hpp>
#include <system_error>

#include "boundary.hpp"

namespace moreau::kernel {

struct LoadedLibrary::Impl {
  boost::dll::shared_library lib;
};

LoadedLibrary::LoadedLibrary(std::filesystem::path path, std::unique_ptr<Impl> impl, const moreau_manifest* m)
    : path_(std::move(path)), impl_(std::move(impl)), manifest_(m) {}

LoadedLibrary::~LoadedLibrary() = default;

LibraryHandle LoadedLibrary::open(const std::filesystem::path& path) {
  const std::string file = path.string();
  auto impl = std::make_unique<Impl>();
  try {
    // Local binding: two plugins may define the same internal symbols. Immediate binding:
    // a symbol the library needs and nothing provides is refused here, with the loader's
    // message, not found at its first call in the middle of a run (exit 127).
    const LoadingLibrary loading(file);
    impl->lib.load(path, boost::dll::load_mode::rtld_now | boost::dll::load_mode::rtld_local);
  } catch (const std::system_error& e) {  // the loader's own failure (dlerror's message)
    throw InputError("", std::string("failed to load plugin library: ") + e.what(), file);
  } catch (const std::exception& e) {
    // A static constructor of the library threw and the exception crossed dlopen (it does
    // under AddressSanitizer's dlopen; otherwise it ends in std::terminate, which
    // guarded.cpp reports in the same words).
    throw InputError("", file + ": the plugin library threw while it was being loaded (a static constructor): " + e.what(),
                     file);
  }
  if (!impl->lib.has("moreau_plugin_manifest"))
    throw InputError("", "not a moreau plugin: the library exports no 'moreau_plugin_manifest' entry point", file);
  const moreau_manifest* m = impl->lib.get_alias<const moreau_manifest*()>("moreau_plugin_manifest")();
  if (m == nullptr) throw InputError("", "not a moreau plugin: its manifest entry point returned nothing", file);
  // abi_version is the first member in every ABI version: safe to read before anything else.
  if (m->abi_version != MOREAU_ABI_VERSION)
    throw InputError("",
                     "plugin ABI mismatch: the library was built for moreau plugin ABI " +
                         std::to_string(m->abi_version) + ", this moreau has ABI " +
                         std::to_string(MOREAU_ABI_VERSION) + " (SDK " MOREAU_SDK_VERSION
                         "); rebuild the plugin against this SDK",
                     file);
  const std::string build = m->build_id ? m->build_id : "";
  if (build != MOREAU_BUILD_ID)
    throw InputError("",
                     "plugin build mismatch: the library was built with '" + build + "', this moreau with '" +
                         MOREAU_BUILD_ID + "' (SDK " + (m->sdk_version ? m->sdk_version : "?") +
                         " vs " MOREAU_SDK_VERSION "); rebuild the plugin with the same compiler and standard library",
                     file);
  if (m->register_all == nullptr) throw InputError("", "plugin manifest has no registration function", file);
  return LibraryHandle(new LoadedLibrary(path, std::move(impl), m));
}

}  // namespace moreau::kernel
