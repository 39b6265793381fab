#pragma once
// Exceptions of the finite-element library. Each carries what a caller needs to point the
// user at the fault: the mesh file and line (or byte offset in a binary file) and the
// element number, or the material parameter. The message alone is complete; the fields
// let the elastic modelization add its JSON pointer.
#include <cstdint>
#include <stdexcept>
#include <string>

namespace moreau::fem {

/// A bad mesh: unreadable or malformed file, unsupported element type, inverted or
/// degenerate element, unknown set name.
class MeshError : public std::runtime_error {
 public:
  MeshError(const std::string& message, std::string file = {}, long line = 0,
            std::int64_t element = 0)
      : std::runtime_error(message), file_(std::move(file)), line_(line), element_(element) {}
  const std::string& file() const { return file_; }  ///< empty for a generated mesh
  long line() const { return line_; }                 ///< 1-based; 0 when unknown or binary
  std::int64_t element() const { return element_; }   ///< element number as the user knows it; 0: none
 private:
  std::string file_;
  long line_;
  std::int64_t element_;
};

/// A material parameter out of its admissible range; `parameter` is "young", "poisson" or
/// "density".
class MaterialError : public std::invalid_argument {
 public:
  MaterialError(const std::string& message, std::string parameter)
      : std::invalid_argument(message), parameter_(std::move(parameter)) {}
  const std::string& parameter() const { return parameter_; }
 private:
  std::string parameter_;
};

}  // namespace moreau::fem
