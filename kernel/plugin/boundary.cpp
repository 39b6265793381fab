#include "boundary.hpp"

#include <moreau/error.hpp>
#include <new>
#include <vector>

namespace moreau::kernel {

namespace {

const char* g_loading = nullptr;

/// Rethrows moreau errors as kernel-made copies; returns the message for anything else.
std::string copy_or_describe(const std::string& who, const std::string& doing) {
  // Each branch copies the text into a new exception constructed here (kernel code, the
  // kernel's vtables); the plugin's exception is destroyed when the handler ends, while
  // its library is still loaded.
  const std::string at = doing.empty() ? "" : " " + doing;
  try {
    throw;
  } catch (const InputErrors& e) {
    std::vector<InputError> copy;
    for (const auto& x : e.errors()) copy.emplace_back(x.where(), std::string(x.what()), x.file());
    throw InputErrors(std::move(copy));
  } catch (const InputError& e) {
    throw InputError(e.where(), std::string(e.what()), e.file());
  } catch (const RunError& e) {
    throw RunError(std::string(e.what()));
  } catch (const std::bad_alloc&) {
    return who + " ran out of memory" + at;
  } catch (const std::exception& e) {
    return who + " failed" + at + ": " + e.what();
  } catch (...) {
    return who + " threw an exception that is not a std::exception (such as `throw 42`)" + at;
  }
}

}  // namespace

void rethrow_kernel_owned(const std::string& who, const std::string& doing) {
  throw RunError(copy_or_describe(who, doing));
}

void rethrow_kernel_owned_input(const std::string& pointer, const std::string& who, const std::string& doing) {
  throw InputError(pointer, copy_or_describe(who, doing));
}

const char* library_being_loaded() { return g_loading; }

LoadingLibrary::LoadingLibrary(const std::string& path) : path_(path), previous_(g_loading) { g_loading = path_.c_str(); }
LoadingLibrary::~LoadingLibrary() { g_loading = previous_; }

}  // namespace moreau::kernel
