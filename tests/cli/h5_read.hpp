#pragma once
// Reading output files in tests, as any HDF5 reader would.
#include <hdf5.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace moreau_test {

inline std::vector<double> read_doubles(const std::string& file, const std::string& path) {
  hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (f < 0) throw std::runtime_error("cannot open " + file);
  hid_t d = H5Dopen2(f, path.c_str(), H5P_DEFAULT);
  if (d < 0) {
    H5Fclose(f);
    throw std::runtime_error("no dataset " + path + " in " + file);
  }
  hid_t s = H5Dget_space(d);
  const hssize_t n = H5Sget_simple_extent_npoints(s);
  std::vector<double> v(static_cast<std::size_t>(n));
  H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data());
  H5Sclose(s);
  H5Dclose(d);
  H5Fclose(f);
  return v;
}

/// Names of the groups under /frames, sorted.
inline std::vector<std::string> frame_names(const std::string& file) {
  std::vector<std::string> names;
  hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (f < 0) throw std::runtime_error("cannot open " + file);
  hid_t g = H5Gopen2(f, "/frames", H5P_DEFAULT);
  H5G_info_t info;
  H5Gget_info(g, &info);
  for (hsize_t i = 0; i < info.nlinks; ++i) {
    char name[64];
    H5Lget_name_by_idx(g, ".", H5_INDEX_NAME, H5_ITER_INC, i, name, sizeof name, H5P_DEFAULT);
    names.emplace_back(name);
  }
  H5Gclose(g);
  H5Fclose(f);
  return names;
}

/// Paths (relative to `group`) of every dataset under group `group` of `file`, sorted.
inline std::vector<std::string> datasets_under(const std::string& file, const std::string& group) {
  std::vector<std::string> names;
  hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (f < 0) throw std::runtime_error("cannot open " + file);
  hid_t g = H5Gopen2(f, group.c_str(), H5P_DEFAULT);
  H5Ovisit(g, H5_INDEX_NAME, H5_ITER_INC,
           [](hid_t, const char* name, const H5O_info_t* info, void* out) -> herr_t {
             if (info->type == H5O_TYPE_DATASET) static_cast<std::vector<std::string>*>(out)->emplace_back(name);
             return 0;
           },
           &names);
  H5Gclose(g);
  H5Fclose(f);
  return names;
}

/// A numeric attribute of the object at `path`, as a double.
inline double read_attribute(const std::string& file, const std::string& path, const std::string& name) {
  hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (f < 0) throw std::runtime_error("cannot open " + file);
  hid_t a = H5Aopen_by_name(f, path.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT);
  double v = 0;
  const herr_t rc = a < 0 ? -1 : H5Aread(a, H5T_NATIVE_DOUBLE, &v);
  if (a >= 0) H5Aclose(a);
  H5Fclose(f);
  if (rc < 0) throw std::runtime_error("no attribute " + name + " on " + path + " in " + file);
  return v;
}

/// Replaces dataset `path` of `file` by `values` as float64, in `rows` rows (1: a vector).
inline void replace_doubles(const std::string& file, const std::string& path, const std::vector<double>& values,
                            hsize_t rows = 0) {
  hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  if (f < 0) throw std::runtime_error("cannot open " + file);
  H5Ldelete(f, path.c_str(), H5P_DEFAULT);
  const hsize_t dims[2] = {rows ? rows : values.size(), rows ? values.size() / rows : 1};
  hid_t s = H5Screate_simple(rows ? 2 : 1, dims, nullptr);
  hid_t d = H5Dcreate2(f, path.c_str(), H5T_IEEE_F64LE, s, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  H5Dwrite(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data());
  H5Dclose(d);
  H5Sclose(s);
  H5Fclose(f);
}

}  // namespace moreau_test
