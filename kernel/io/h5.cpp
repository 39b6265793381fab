#include "h5.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <moreau/error.hpp>
#include <stdexcept>

namespace moreau::io::h5 {

namespace {
void check(herr_t rc, const std::string& what) {
  if (rc < 0) throw RunError("HDF5 write failed: " + what);
}

/// The values a dataset or attribute holds; refuses a size no machine holds (a damaged
/// file may declare 2^40 values in a few bytes: allocating them would be killed by the OS).
std::size_t value_count(hid_t space, std::size_t value_size, const std::string& path, const std::string& file) {
  const hssize_t n = space >= 0 ? H5Sget_simple_extent_npoints(space) : -1;
  if (n < 0) throw InputError(path, "cannot read the dataset's shape", file);
  static const double memory = static_cast<double>(sysconf(_SC_PHYS_PAGES)) * static_cast<double>(sysconf(_SC_PAGE_SIZE));
  if (static_cast<double>(n) * static_cast<double>(value_size) > memory / 2)
    throw InputError(path, "the dataset declares " + std::to_string(n) + " values: more than half this machine's memory",
                     file);
  return static_cast<std::size_t>(n);
}

/// The transfer of `n` variable-length strings. They are always converted (memory pointers
/// <-> the file's heap references), and HDF5 1.10 allocates and zeroes a conversion and a
/// background buffer of the transfer's buffer size at every H5Dwrite/H5Dread that converts:
/// 1 MiB each by default, which made a frame's few strings (analyses' column names) cost
/// more than all its numbers (page faults and memset). Sized to the data instead (the next
/// power of two of 32 bytes a string, more than either side's element: a pointer, a 16-byte
/// heap reference), at most the default, beyond which HDF5 converts in several passes as
/// it always did. One property list per size, made once: making one costs as much as the
/// small write itself. H5P_DEFAULT should it not be made.
hid_t strings_transfer(std::size_t n) {
  constexpr int smallest = 9, largest = 20;  // 512 B .. 1 MiB
  static hid_t lists[largest + 1] = {};
  int k = smallest;
  while (k < largest && (std::size_t{1} << k) < 32 * n) ++k;
  hid_t& dxpl = lists[k];
  if (dxpl > 0 && H5Iis_valid(dxpl) > 0) return dxpl;
  dxpl = H5Pcreate(H5P_DATASET_XFER);
  if (dxpl < 0 || H5Pset_buffer(dxpl, std::size_t{1} << k, nullptr, nullptr) < 0) {
    if (dxpl >= 0) H5Pclose(dxpl);
    dxpl = 0;
    return H5P_DEFAULT;
  }
  return dxpl;
}

/// An attribute must hold one value: reading an array into one would overrun it.
void require_one_value(hid_t attr, const std::string& name, const std::string& file, const std::string& path) {
  Id sp = space(H5Aget_space(attr));
  if (!sp || H5Sget_simple_extent_npoints(sp.get()) != 1)
    throw InputError(path, "attribute '" + name + "' should hold one value", file);
}
}  // namespace

namespace {

// HDF5 cleans up at exit (atexit). After a failed H5Fclose its list of open files holds a
// half-destroyed one, and that cleanup crashes (SIGSEGV in H5F__close_cb): every file of
// moreau is closed by its owner before exit, so the library's own cleanup is switched off,
// before anything else initialises the library.
const bool no_hdf5_atexit = [] {
  H5dont_atexit();
  return true;
}();

Id file_access() {
  Id fapl = plist(H5Pcreate(H5P_FILE_ACCESS));
  H5Pset_libver_bounds(fapl.get(), H5F_LIBVER_V18, H5F_LIBVER_V18);
  return fapl;
}

herr_t find_errno_text(unsigned, const H5E_error2_t* e, void* out) {
  // The sec2 driver's message: "... errno = 28, error message = 'No space left on device', ..."
  const std::string desc = e->desc ? e->desc : "";
  const std::string key = "error message = '";
  if (auto p = desc.find(key); p != std::string::npos) {
    const auto start = p + key.size(), end = desc.find('\'', start);
    *static_cast<std::string*>(out) = desc.substr(start, end == std::string::npos ? std::string::npos : end - start);
  }
  return 0;
}

}  // namespace

namespace {
// The core driver's memory, through these callbacks so that the final image is ours.
//
// The driver grows a file by its increment at a time and zeroes each new piece. A
// megabyte (as before) made every frame file, of tens of kB, zero and fault in a megabyte
// of fresh memory: a third of a frame's cost on a 600-body scene. With a small increment
// the driver asks for memory often, so the block grows geometrically here (the driver
// still zeroes only what it uses): a frame of many megabytes is not copied at every step.
// Neither changes a byte of the file.
constexpr std::size_t core_increment = std::size_t{1} << 16;

void* image_malloc(std::size_t n, H5FD_file_image_op_t, void* udata) {
  auto* image = static_cast<MemoryFile::Image*>(udata);
  void* p = std::malloc(n);
  if (p && !image->block) {
    image->block = p;
    image->capacity = n;
  }
  return p;
}
void* image_memcpy(void* d, const void* s, std::size_t n, H5FD_file_image_op_t, void*) { return std::memcpy(d, s, n); }
void* image_realloc(void* p, std::size_t n, H5FD_file_image_op_t, void* udata) {
  auto* image = static_cast<MemoryFile::Image*>(udata);
  if (!p || p != image->block) return std::realloc(p, n);
  if (n <= image->capacity) return p;
  const std::size_t capacity = std::max(n, 2 * image->capacity);
  void* q = std::realloc(p, capacity);
  if (q) {
    image->block = q;
    image->capacity = capacity;
  }
  return q;
}
herr_t image_free(void* p, H5FD_file_image_op_t op, void* udata) {
  auto* image = static_cast<MemoryFile::Image*>(udata);
  if (p && p == image->block) {
    image->block = nullptr;
    image->capacity = 0;
  }
  if (op == H5FD_FILE_IMAGE_OP_FILE_CLOSE && image->keep && !image->bytes) image->bytes = static_cast<char*>(p);
  else std::free(p);
  return 0;
}
void* udata_copy(void* udata) { return udata; }  // one Image per file, owned by its MemoryFile
herr_t udata_free(void*) { return 0; }
}  // namespace

MemoryFile::Image::~Image() { std::free(bytes); }

MemoryFile::MemoryFile(const std::string& name) : image_(std::make_unique<Image>()) {
  quiet();
  Id fapl = file_access();
  H5Pset_fapl_core(fapl.get(), core_increment, /*backing_store=*/0);
  H5FD_file_image_callbacks_t callbacks{image_malloc, image_memcpy, image_realloc, image_free,
                                        udata_copy,   udata_free,   image_.get()};
  H5Pset_file_image_callbacks(fapl.get(), &callbacks);
  file_ = file(H5Fcreate(name.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl.get()));
}

Id create_on_disk(const std::string& path) {
  quiet();
  return file(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, file_access().get()));
}

Id open_whole(const std::string& path) {
  quiet();
  Id fapl = plist(H5Pcreate(H5P_FILE_ACCESS));
  H5Pset_fapl_core(fapl.get(), core_increment, /*backing_store=*/0);
  return file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, fapl.get()));
}

std::string last_os_error() {
  std::string text;
  H5Ewalk2(H5E_DEFAULT, H5E_WALK_DOWNWARD, find_errno_text, &text);
  return text;
}

void MemoryFile::save(const std::string& path) {
  if (!file_ || H5Fflush(file_.get(), H5F_SCOPE_LOCAL) < 0) throw RunError("HDF5 could not finish " + path + " in memory");
  const ssize_t size = H5Fget_file_image(file_.get(), nullptr, 0);  // the end of the file
  image_->keep = true;
  file_.reset();  // in memory: closing writes nothing; the driver hands the image over
  if (size < 0 || !image_->bytes) throw RunError("HDF5 could not finish " + path + " in memory");
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd < 0) throw RunError("cannot write " + path + ": " + std::strerror(errno));
  std::size_t done = 0;
  int error = 0;
  while (done < static_cast<std::size_t>(size) && !error) {
    const ssize_t n = ::write(fd, image_->bytes + done, static_cast<std::size_t>(size) - done);
    if (n > 0) done += static_cast<std::size_t>(n);
    else if (n < 0 && errno != EINTR) error = errno;
    else if (n == 0) error = EIO;
  }
  if (::close(fd) != 0 && !error) error = errno;
  if (error) {
    ::unlink(path.c_str());
    throw RunError("cannot write " + path + ": " + std::strerror(error));
  }
}

void MemoryFile::save_atomically(const std::string& path) {
  const std::string part = path + ".part";
  save(part);
  std::error_code ec;
  std::filesystem::rename(part, path, ec);
  if (ec) {
    std::filesystem::remove(part, ec);
    throw RunError("cannot rename " + part + " to " + path + ": " + ec.message());
  }
}

void close_on_disk(Id& f, const std::string& path) {
  const hid_t id = f.get();
  f.release();
  if (H5Fclose(id) < 0) {
    const std::string why = last_os_error();
    throw RunError("cannot write " + path + (why.empty() ? ": HDF5 could not write it out" : ": " + why));
  }
}

hid_t group_creation() {
  static hid_t gcpl = -1;
  if (gcpl >= 0 && H5Iis_valid(gcpl) > 0) return gcpl;
  gcpl = H5Pcreate(H5P_GROUP_CREATE);
  if (gcpl < 0 || H5Pset_link_phase_change(gcpl, 64, 48) < 0) {
    if (gcpl >= 0) H5Pclose(gcpl);
    gcpl = -1;
    return H5P_DEFAULT;
  }
  return gcpl;
}

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
  if (ptrs.empty()) return;
  check(H5Dwrite(ds.get(), t.get(), H5S_ALL, H5S_ALL, strings_transfer(ptrs.size()), ptrs.data()), name);
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
  if (path.empty()) return false;
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
  const std::size_t n = value_count(sp.get(), sizeof(double), path, file);
  const int rank = H5Sget_simple_extent_ndims(sp.get());
  std::vector<hsize_t> dims(std::max(rank, 0));
  if (rank > 0) H5Sget_simple_extent_dims(sp.get(), dims.data(), nullptr);
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
  if (!a) throw InputError(path, "cannot open attribute '" + name + "'", file);
  require_one_value(a.get(), name, file, path);
  double v = 0;
  if (H5Aread(a.get(), H5T_NATIVE_DOUBLE, &v) < 0) throw InputError(path, "cannot read attribute '" + name + "'", file);
  return v;
}

std::string read_attribute_string(hid_t where, const std::string& name, const std::string& file, const std::string& path) {
  if (H5Aexists(where, name.c_str()) <= 0) throw InputError(path, "missing attribute '" + name + "'", file);
  Id a = attribute(H5Aopen(where, name.c_str(), H5P_DEFAULT));
  if (!a) throw InputError(path, "cannot open attribute '" + name + "'", file);
  require_one_value(a.get(), name, file, path);
  Id t = type(H5Aget_type(a.get()));
  if (!t) throw InputError(path, "cannot read attribute '" + name + "'", file);
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
  if (n == 0 || n > (1u << 30)) throw InputError(path, "attribute '" + name + "' has an unreadable size", file);
  std::string s(n, '\0');
  if (H5Aread(a.get(), t.get(), s.data()) < 0) throw InputError(path, "cannot read attribute '" + name + "'", file);
  return s.substr(0, s.find('\0'));
}

std::vector<std::string> read_strings(hid_t where, const std::string& path, const std::string& file) {
  if (!exists(where, path)) throw InputError(path, "missing dataset", file);
  Id ds = dataset(H5Dopen2(where, path.c_str(), H5P_DEFAULT));
  if (!ds) throw InputError(path, "cannot open the dataset", file);
  {
    Id ft = type(H5Dget_type(ds.get()));
    if (!ft || H5Tget_class(ft.get()) != H5T_STRING) throw InputError(path, "expected a dataset of strings", file);
  }
  Id sp = space(H5Dget_space(ds.get()));
  const std::size_t n = value_count(sp.get(), sizeof(char*), path, file);
  Id t = type(H5Tcopy(H5T_C_S1));
  H5Tset_size(t.get(), H5T_VARIABLE);
  H5Tset_cset(t.get(), H5T_CSET_UTF8);
  std::vector<char*> ptrs(n, nullptr);
  if (n > 0 && H5Dread(ds.get(), t.get(), H5S_ALL, H5S_ALL, strings_transfer(n), ptrs.data()) < 0)
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
