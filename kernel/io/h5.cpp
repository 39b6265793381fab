#include "h5.hpp"

#include <algorithm>
#include <moreau/error.hpp>
#include <stdexcept>

namespace moreau::io::h5 {

namespace {
void check(herr_t rc, const std::string& what) {
  if (rc < 0) throw RunError("HDF5 write failed: " + what);
}
}  // namespace

void write_doubles(hid_t where, const std::string& name, const double* data, hsize_t rows, hsize_t cols) {
  const hsize_t dims[2] = {rows, cols};
  Id sp = space(H5Screate_simple(cols == 0 ? 1 : 2, dims, nullptr));
  Id ds = dataset(H5Dcreate2(where, name.c_str(), H5T_IEEE_F64LE, sp.get(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
  if (!ds) throw RunError("HDF5 write failed: dataset " + name);
  if (rows * std::max<hsize_t>(cols, 1) > 0)
    check(H5Dwrite(ds.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), name);
}

void write_floats(hid_t where, const std::string& name, const float* data, hsize_t rows, hsize_t cols) {
  const hsize_t dims[2] = {rows, cols};
  Id sp = space(H5Screate_simple(cols == 0 ? 1 : 2, dims, nullptr));
  Id ds = dataset(H5Dcreate2(where, name.c_str(), H5T_IEEE_F32LE, sp.get(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
  if (!ds) throw RunError("HDF5 write failed: dataset " + name);
  if (rows * std::max<hsize_t>(cols, 1) > 0)
    check(H5Dwrite(ds.get(), H5T_NATIVE_FLOAT, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), name);
}

void write_int8(hid_t where, const std::string& name, const std::vector<signed char>& data) {
  const hsize_t dims[1] = {data.size()};
  Id sp = space(H5Screate_simple(1, dims, nullptr));
  Id ds = dataset(H5Dcreate2(where, name.c_str(), H5T_STD_I8LE, sp.get(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
  if (!ds) throw RunError("HDF5 write failed: dataset " + name);
  if (!data.empty()) check(H5Dwrite(ds.get(), H5T_NATIVE_SCHAR, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data()), name);
}

void write_int32(hid_t where, const std::string& name, const int* data, hsize_t rows, hsize_t cols) {
  const hsize_t dims[2] = {rows, cols};
  Id sp = space(H5Screate_simple(cols == 0 ? 1 : 2, dims, nullptr));
  Id ds = dataset(H5Dcreate2(where, name.c_str(), H5T_STD_I32LE, sp.get(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
  if (!ds) throw RunError("HDF5 write failed: dataset " + name);
  if (rows > 0) check(H5Dwrite(ds.get(), H5T_NATIVE_INT, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), name);
}

void write_strings(hid_t where, const std::string& name, const std::vector<std::string>& strings) {
  Id t = type(H5Tcopy(H5T_C_S1));
  H5Tset_size(t.get(), H5T_VARIABLE);
  H5Tset_cset(t.get(), H5T_CSET_UTF8);
  const hsize_t dims[1] = {strings.size()};
  Id sp = space(H5Screate_simple(1, dims, nullptr));
  Id ds = dataset(H5Dcreate2(where, name.c_str(), t.get(), sp.get(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
  if (!ds) throw RunError("HDF5 write failed: dataset " + name);
  std::vector<const char*> ptrs;
  for (const auto& s : strings) ptrs.push_back(s.c_str());
  if (!ptrs.empty()) check(H5Dwrite(ds.get(), t.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, ptrs.data()), name);
}

static void attribute(hid_t where, const std::string& name, hid_t file_type, hid_t mem_type, const void* value) {
  Id sp = space(H5Screate(H5S_SCALAR));
  Id a = attribute(H5Acreate2(where, name.c_str(), file_type, sp.get(), H5P_DEFAULT, H5P_DEFAULT));
  if (!a) throw RunError("HDF5 write failed: attribute " + name);
  check(H5Awrite(a.get(), mem_type, value), name);
}

void attribute_double(hid_t where, const std::string& name, double value) {
  attribute(where, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &value);
}

void attribute_long(hid_t where, const std::string& name, long value) {
  attribute(where, name, H5T_STD_I64LE, H5T_NATIVE_LONG, &value);
}

void attribute_string(hid_t where, const std::string& name, const std::string& value) {
  Id t = type(H5Tcopy(H5T_C_S1));
  H5Tset_size(t.get(), H5T_VARIABLE);
  H5Tset_cset(t.get(), H5T_CSET_UTF8);
  const char* p = value.c_str();
  attribute(where, name, t.get(), t.get(), &p);
}

void link(hid_t where, const std::string& target, const std::string& name) {
  check(H5Lcreate_hard(where, target.c_str(), where, name.c_str(), H5P_DEFAULT, H5P_DEFAULT), "link " + name + " -> " + target);
}

bool exists(hid_t where, const std::string& path) {
  // Check each level: H5Lexists fails on a missing intermediate group.
  std::string partial;
  std::size_t start = path[0] == '/' ? 1 : 0;
  if (start) partial = "/";
  while (start <= path.size()) {
    const std::size_t end = path.find('/', start);
    partial += path.substr(start, end - start);
    if (H5Lexists(where, partial.c_str(), H5P_DEFAULT) <= 0) return false;
    if (end == std::string::npos) break;
    partial += "/";
    start = end + 1;
  }
  return true;
}

std::vector<double> read_doubles(hid_t where, const std::string& path, std::vector<hsize_t>* shape,
                                 const std::string& file) {
  if (!exists(where, path)) throw InputError(path, "missing dataset", file);
  Id ds = dataset(H5Dopen2(where, path.c_str(), H5P_DEFAULT));
  if (!ds) throw InputError(path, "cannot open the dataset", file);
  Id sp = space(H5Dget_space(ds.get()));
  const int rank = H5Sget_simple_extent_ndims(sp.get());
  std::vector<hsize_t> dims(std::max(rank, 0));
  if (rank > 0) H5Sget_simple_extent_dims(sp.get(), dims.data(), nullptr);
  hsize_t n = 1;
  for (auto d : dims) n *= d;
  std::vector<double> v(n);
  if (n > 0 && H5Dread(ds.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()) < 0)
    throw InputError(path, "cannot read the dataset as numbers", file);
  if (shape) *shape = dims;
  return v;
}

std::vector<hsize_t> dimensions(hid_t where, const std::string& path) {
  if (!exists(where, path)) return {};
  Id ds = dataset(H5Dopen2(where, path.c_str(), H5P_DEFAULT));
  if (!ds) return {};
  Id sp = space(H5Dget_space(ds.get()));
  const int rank = H5Sget_simple_extent_ndims(sp.get());
  std::vector<hsize_t> dims(std::max(rank, 0));
  if (rank > 0) H5Sget_simple_extent_dims(sp.get(), dims.data(), nullptr);
  return dims;
}

double read_attribute_double(hid_t where, const std::string& name, const std::string& file, const std::string& path) {
  if (H5Aexists(where, name.c_str()) <= 0) throw InputError(path, "missing attribute '" + name + "'", file);
  Id a = attribute(H5Aopen(where, name.c_str(), H5P_DEFAULT));
  double v = 0;
  if (H5Aread(a.get(), H5T_NATIVE_DOUBLE, &v) < 0) throw InputError(path, "cannot read attribute '" + name + "'", file);
  return v;
}

std::string read_attribute_string(hid_t where, const std::string& name, const std::string& file, const std::string& path) {
  if (H5Aexists(where, name.c_str()) <= 0) throw InputError(path, "missing attribute '" + name + "'", file);
  Id a = attribute(H5Aopen(where, name.c_str(), H5P_DEFAULT));
  Id t = type(H5Aget_type(a.get()));
  if (H5Tget_class(t.get()) != H5T_STRING) throw InputError(path, "attribute '" + name + "' is not a string", file);
  if (H5Tis_variable_str(t.get()) > 0) {
    char* p = nullptr;
    Id mt = type(H5Tcopy(H5T_C_S1));
    H5Tset_size(mt.get(), H5T_VARIABLE);
    H5Tset_cset(mt.get(), H5Tget_cset(t.get()));
    if (H5Aread(a.get(), mt.get(), &p) < 0 || !p) throw InputError(path, "cannot read attribute '" + name + "'", file);
    std::string s(p);
    H5free_memory(p);
    return s;
  }
  const std::size_t n = H5Tget_size(t.get());
  std::string s(n, '\0');
  H5Aread(a.get(), t.get(), s.data());
  return s.substr(0, s.find('\0'));
}

std::vector<std::string> read_strings(hid_t where, const std::string& path, const std::string& file) {
  if (!exists(where, path)) throw InputError(path, "missing dataset", file);
  Id ds = dataset(H5Dopen2(where, path.c_str(), H5P_DEFAULT));
  Id sp = space(H5Dget_space(ds.get()));
  const hssize_t n = H5Sget_simple_extent_npoints(sp.get());
  Id t = type(H5Tcopy(H5T_C_S1));
  H5Tset_size(t.get(), H5T_VARIABLE);
  H5Tset_cset(t.get(), H5T_CSET_UTF8);
  std::vector<char*> ptrs(static_cast<std::size_t>(n), nullptr);
  if (n > 0 && H5Dread(ds.get(), t.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, ptrs.data()) < 0)
    throw InputError(path, "cannot read the names", file);
  std::vector<std::string> out;
  for (char* p : ptrs) {
    out.emplace_back(p ? p : "");
    H5free_memory(p);
  }
  return out;
}

std::vector<std::string> children(hid_t g) {
  std::vector<std::string> names;
  H5G_info_t info;
  if (H5Gget_info(g, &info) < 0) return names;
  for (hsize_t i = 0; i < info.nlinks; ++i) {
    const ssize_t len = H5Lget_name_by_idx(g, ".", H5_INDEX_NAME, H5_ITER_INC, i, nullptr, 0, H5P_DEFAULT);
    if (len < 0) continue;
    std::string name(static_cast<std::size_t>(len) + 1, '\0');
    H5Lget_name_by_idx(g, ".", H5_INDEX_NAME, H5_ITER_INC, i, name.data(), name.size(), H5P_DEFAULT);
    name.resize(static_cast<std::size_t>(len));
    names.push_back(name);
  }
  std::sort(names.begin(), names.end());
  return names;
}

}  // namespace moreau::io::h5
