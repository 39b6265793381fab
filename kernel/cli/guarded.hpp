#pragma once
#include <moreau/error.hpp>
#include <ostream>

namespace moreau::kernel {

/// Once at start: SIGPIPE and SIGXFSZ ignored (a closed pipe or a file-size limit then
/// fails the write, which is reported, instead of killing the process), and a terminate
/// handler that names what threw (a plugin library's static constructor, whose exception
/// the dynamic loader cannot pass on) and exits instead of aborting.
void install_process_guards();

template <class F>
int guarded(std::ostream& err, F&& body) {
  try {
    return body();
  } catch (const InputErrors& e) {
    for (const auto& x : e.errors()) err << "error: " << x.describe() << "\n";
    err << e.errors().size() << " error" << (e.errors().size() == 1 ? "" : "s") << "\n";
    return 2;
  } catch (const InputError& e) {
    err << "error: " << e.describe() << "\n";
    return 2;
  } catch (const RunError& e) {
    err << "run failed: " << e.what() << "\n";
    return 1;
  } catch (const std::exception& e) {
    err << "internal error: " << e.what() << "\n";
    return 1;
  } catch (...) {
    err << "internal error: an exception that is not a std::exception\n";
    return 1;
  }
}

}  // namespace moreau::kernel
