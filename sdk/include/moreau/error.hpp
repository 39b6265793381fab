#pragma once
// The two kinds of failure a user sees, mapped to the exit codes of DESIGN §3.1:
//  - InputError: the input is wrong (scene, file, usage); exit code 2. Carries the file
//    and the JSON pointer (or HDF5 path) of the fault, and what was expected.
//  - RunError: the input was fine but the run failed (non-convergence with
//    on_failure = stop, non-finite values, I/O failure); exit code 1.
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace moreau {

class InputError : public std::runtime_error {
 public:
  /// `where` is a JSON pointer ("/bodies/3/radius"), an HDF5 path, or empty.
  InputError(std::string where, const std::string& what, std::string file = {})
      : std::runtime_error(what), where_(std::move(where)), file_(std::move(file)) {}
  const std::string& where() const { return where_; }
  const std::string& file() const { return file_; }
  /// The message as printed: "FILE: at POINTER: WHAT".
  std::string describe() const {
    std::string s;
    if (!file_.empty()) s += file_ + ": ";
    if (!where_.empty()) s += "at " + where_ + ": ";
    return s + what();
  }
  InputError with_file(const std::string& file) const {
    return InputError(where_, what(), file_.empty() ? file : file_);
  }

 private:
  std::string where_;
  std::string file_;
};

/// Several input errors found in one pass (scene validation reports all at once).
class InputErrors : public std::runtime_error {
 public:
  explicit InputErrors(std::vector<InputError> errors)
      : std::runtime_error(join(errors)), errors_(std::move(errors)) {}
  const std::vector<InputError>& errors() const { return errors_; }

 private:
  static std::string join(const std::vector<InputError>& errors) {
    std::string s;
    for (const auto& e : errors) s += e.describe() + "\n";
    return s;
  }
  std::vector<InputError> errors_;
};

class RunError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace moreau
