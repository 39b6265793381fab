#pragma once
// Exceptions crossing from plugin code into the kernel.
//
// An exception a plugin throws is an object of the plugin's library: its vtable, its
// destructor and, for a class the plugin defines, its what() are code of that library.
// The kernel may unload the library while unwinding (the objects that kept it loaded go
// away with the World), after which printing the message jumps into unmapped memory. So
// every place that calls plugin code and outlives it catches what it throws and throws
// instead an exception the kernel made (InputError, InputErrors or RunError, with the text
// copied), before the library can be released. The same place turns anything that is not a
// moreau error (std::exception, `throw 42`) into a RunError naming the plugin.
#include <string>

namespace moreau::kernel {

/// Call only inside a catch block: rethrows the exception being handled as a kernel-owned
/// one. InputError(s) and RunError keep their text; anything else becomes a RunError
/// "WHO failed DOING: what" (`who`: "the hook 'energy_log' (/hooks/0)", `doing`: "at step 12").
[[noreturn]] void rethrow_kernel_owned(const std::string& who, const std::string& doing = "");
/// Same, but anything that is not a moreau error becomes an InputError at `pointer`: for
/// plugin code that checks input (a constructor checking its parameters).
[[noreturn]] void rethrow_kernel_owned_input(const std::string& pointer, const std::string& who,
                                             const std::string& doing = "");

/// Runs `body` (which calls plugin code) with its exceptions made kernel-owned.
template <class F>
decltype(auto) plugin_call(const std::string& who, const std::string& doing, F&& body) {
  try {
    return body();
  } catch (...) {
    rethrow_kernel_owned(who, doing);
  }
}

/// While a plugin library is being loaded (its static constructors run inside the dynamic
/// loader, where an exception cannot be caught), the path of that library; else nullptr.
/// Read by the terminate handler (cli/guarded.cpp) to name the library.
const char* library_being_loaded();

/// Sets library_being_loaded() for the lifetime of the object.
class LoadingLibrary {
 public:
  explicit LoadingLibrary(const std::string& path);
  ~LoadingLibrary();
  LoadingLibrary(const LoadingLibrary&) = delete;
  LoadingLibrary& operator=(const LoadingLibrary&) = delete;

 private:
  std::string path_;
  const char* previous_;
};

}  // namespace moreau::kernel
