#pragma once
// Writing small HDF5 datasets in tests (FCLib files made by hand).
#include <hdf5.h>

#include <type_traits>
#include <vector>

namespace moreau_test {

/// A 1D dataset at `path` of file `f`: 32-bit integers for int, doubles for double.
template <class T>
void h5_write(hid_t f, const char* path, const std::vector<T>& v) {
  static_assert(std::is_same_v<T, int> || std::is_same_v<T, double>);
  const bool ints = std::is_same_v<T, int>;
  hsize_t n = v.size();
  hid_t s = H5Screate_simple(1, &n, nullptr);
  hid_t d = H5Dcreate2(f, path, ints ? H5T_STD_I32LE : H5T_IEEE_F64LE, s, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  H5Dwrite(d, ints ? H5T_NATIVE_INT : H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data());
  H5Dclose(d);
  H5Sclose(s);
}

}  // namespace moreau_test
