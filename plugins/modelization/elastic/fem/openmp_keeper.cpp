// Compiled into every target that links moreau_fem with CHOLMOD (an INTERFACE source of
// moreau_fem, fem/CMakeLists.txt), because each such plugin brings libgomp (OpenMP) in
// through libcholmod, whether or not it ever factorises: the elastic modelization alone is
// loaded (and unloaded) when a scene's mesh is rejected before the integrator is.
//
// libgomp is not made to be unloaded with the plugin that brought it: it keeps memory it
// allocates when it loads in a global of its own (LeakSanitizer reports it as a leak once the
// library is gone: 8 bytes at the end of every run or check of a scene with an elastic body),
// and CHOLMOD's supernodal factorisation runs OpenMP loops (4 threads in Debian's
// libcholmod) whose idle threads would be left in code no longer mapped (a segfault at exit
// in ~1 run of 30). So libgomp stays loaded for the life of the process (RTLD_NODELETE on
// the already loaded library, the handle never closed), as if the program had linked it.
#include <dlfcn.h>

namespace {
[[maybe_unused]] const bool gomp_kept_loaded = dlopen("libgomp.so.1", RTLD_NOW | RTLD_NOLOAD | RTLD_NODELETE) != nullptr;
}  // namespace
