#include "field_io.hpp"

#include <moreau/error.hpp>
#include <vector>

#include "h5.hpp"

namespace moreau::io {

void write_field(hid_t where, const std::string& name, const Field& f, Depth depth) {
  const std::size_t rows = f.rows();
  const hsize_t cols = f.components() == 1 ? 0 : static_cast<hsize_t>(f.components());
  const double* p = f.data(depth);
  const std::size_t n = rows * static_cast<std::size_t>(f.components());
  switch (f.spec().file) {
    case FileType::real:
      h5::write_doubles(where, name, p, rows, cols);
      return;
    case FileType::int8:
      if (cols == 0) {
        std::vector<signed char> v(n);
        for (std::size_t i = 0; i < n; ++i) v[i] = static_cast<signed char>(p[i]);
        h5::write_int8(where, name, v);
        return;
      }
      [[fallthrough]];  // several components: int32
    case FileType::int32: {
      std::vector<int> v(n);
      for (std::size_t i = 0; i < n; ++i) v[i] = static_cast<int>(p[i]);
      h5::write_int32(where, name, v.data(), rows, cols);
      return;
    }
  }
}

void read_field(hid_t where, const std::string& path, Field& f, const std::string& file) {
  const auto v = h5::read_doubles(where, path, nullptr, file);
  const std::size_t want = f.rows() * static_cast<std::size_t>(f.components());
  if (v.size() != want)
    throw InputError(path, "expected " + std::to_string(want) + " values (" + std::to_string(f.rows()) + " rows of " +
                               std::to_string(f.components()) + "), found " + std::to_string(v.size()),
                     file);
  for (int d = 0; d < f.spec().depths; ++d) std::copy(v.begin(), v.end(), f.data(static_cast<Depth>(d)));
}

}  // namespace moreau::io
