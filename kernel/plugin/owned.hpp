#pragma once
// An object created by a plugin, together with a handle that keeps the plugin's shared
// library loaded for as long as the object lives (DESIGN §3.4): the library is
// released only after the object's destructor, which is code inside that library, ran.
#include <memory>
#include <string>
#include <utility>

namespace moreau::kernel {

class LoadedLibrary;
using LibraryHandle = std::shared_ptr<const LoadedLibrary>;

template <class T>
class Owned {
 public:
  Owned() = default;
  Owned(LibraryHandle lib, std::unique_ptr<T> obj, std::string label = {})
      : lib_(std::move(lib)), obj_(std::move(obj)), label_(std::move(label)) {}
  Owned(Owned&&) noexcept = default;
  Owned& operator=(Owned&& o) noexcept {
    obj_.reset();  // destroy our object while its library is still held
    obj_ = std::move(o.obj_);
    lib_ = std::move(o.lib_);
    label_ = std::move(o.label_);
    return *this;
  }
  ~Owned() { obj_.reset(); }

  T* get() const { return obj_.get(); }
  T* operator->() const { return obj_.get(); }
  T& operator*() const { return *obj_; }
  explicit operator bool() const { return static_cast<bool>(obj_); }
  const LibraryHandle& library() const { return lib_; }
  /// Which plugin made the object, for messages: "the hook 'energy_log' (/hooks/0)".
  const std::string& label() const { return label_; }

 private:
  LibraryHandle lib_;  // declared first, destroyed last
  std::unique_ptr<T> obj_;
  std::string label_;
};

}  // namespace moreau::kernel
