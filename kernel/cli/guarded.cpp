#include "guarded.hpp"

#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <exception>
#include <string>

#include "../plugin/boundary.hpp"

namespace moreau::kernel {

namespace {

[[noreturn]] void on_terminate() {
  std::string what = "an exception that is not a std::exception";
  if (auto e = std::current_exception()) {
    try {
      std::rethrow_exception(e);
    } catch (const std::exception& x) {
      what = x.what();
    } catch (...) {
    }
  } else {
    what = "";
  }
  if (const char* lib = library_being_loaded()) {
    // A static constructor of the library threw while the loader ran it.
    std::fprintf(stderr, "error: %s: the plugin library threw while it was being loaded (a static constructor): %s\n",
                 lib, what.c_str());
    std::fflush(stderr);
    _exit(2);
  }
  std::fprintf(stderr, "internal error: %s%s\n", what.empty() ? "std::terminate called" : "uncaught exception: ",
               what.c_str());
  std::fflush(stderr);
  _exit(1);
}

}  // namespace

void install_process_guards() {
  std::signal(SIGPIPE, SIG_IGN);
  std::signal(SIGXFSZ, SIG_IGN);
  std::set_terminate(on_terminate);
}

}  // namespace moreau::kernel
