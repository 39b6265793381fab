#pragma once
#include <moreau/error.hpp>
#include <ostream>

namespace moreau::kernel {

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
  }
}

}  // namespace moreau::kernel
