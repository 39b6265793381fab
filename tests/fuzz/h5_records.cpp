#include "h5_records.hpp"

#include <hdf5.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <vector>

namespace moreau_fuzz {

namespace {

class Reader {
 public:
  Reader(const std::uint8_t* d, std::size_t n) : d_(d), n_(n) {}
  bool done() const { return i_ >= n_; }
  std::uint8_t u8() { return i_ < n_ ? d_[i_++] : 0; }
  std::uint16_t u16() { return static_cast<std::uint16_t>(u8() | (u8() << 8)); }
  void bytes(void* out, std::size_t k) {
    auto* o = static_cast<std::uint8_t*>(out);
    for (std::size_t j = 0; j < k; ++j) o[j] = u8();
  }
  std::string str(std::size_t len) {
    std::string s(len, '\0');
    bytes(s.data(), len);
    return s;
  }

 private:
  const std::uint8_t* d_;
  std::size_t n_, i_ = 0;
};

struct Closer {
  hid_t id;
  herr_t (*close)(hid_t);
  ~Closer() {
    if (id >= 0) close(id);
  }
};

hid_t file_type(int t) {
  switch (t) {
    case 0: return H5T_IEEE_F64LE;
    case 1: return H5T_STD_I32LE;
    case 4: return H5T_IEEE_F32LE;
    case 5: return H5T_STD_I8LE;
    default: return H5T_STD_I64LE;
  }
}
std::size_t value_size(int t) {
  switch (t) {
    case 0: case 6: return 8;
    case 1: case 4: return 4;
    default: return 1;
  }
}

/// One dataset or attribute: its values, then created under `where` (as `name`).
void write_object(Reader& in, hid_t file, int kind, const std::string& path, const std::string& attr) {
  const int type = in.u8() % 7;
  const int rank = in.u8() % 3;
  hsize_t dims[2] = {1, 1};
  std::size_t count = 1;
  for (int r = 0; r < rank; ++r) {
    dims[r] = in.u16();
    count *= dims[r];
  }
  if (count > kMaxElements) {
    dims[0] = std::min<hsize_t>(dims[0], kMaxElements);
    if (rank == 2) dims[1] = std::max<hsize_t>(1, std::min<hsize_t>(dims[1], kMaxElements / dims[0]));
    count = rank == 0 ? 1 : dims[0] * (rank == 2 ? dims[1] : 1);
  }
  const bool strings = type == 2 || type == 3;
  std::vector<std::string> text;
  std::vector<std::uint8_t> raw;
  if (strings) {
    text.resize(count);
    for (auto& s : text) s = in.str(in.u16());  // up to 64 KiB: a scene text is longer than 4 KiB
  } else {
    raw.resize(count * value_size(type));
    in.bytes(raw.data(), raw.size());
  }
  Closer space{rank == 0 ? H5Screate(H5S_SCALAR) : H5Screate_simple(rank, dims, nullptr), H5Sclose};
  Closer mtype{-1, H5Tclose};
  hid_t ftype;
  std::vector<const char*> ptrs;
  std::vector<char> fixed;
  const void* buf = raw.data();
  if (strings) {
    mtype.id = H5Tcopy(H5T_C_S1);
    if (type == 2) {
      H5Tset_size(mtype.id, H5T_VARIABLE);
      for (auto& s : text) ptrs.push_back(s.c_str());
      buf = ptrs.data();
    } else {
      H5Tset_size(mtype.id, 16);
      fixed.assign(count * 16, '\0');
      for (std::size_t k = 0; k < count; ++k) std::memcpy(&fixed[16 * k], text[k].data(), std::min<std::size_t>(16, text[k].size()));
      buf = fixed.data();
    }
    H5Tset_cset(mtype.id, H5T_CSET_UTF8);
    ftype = mtype.id;
  } else {
    ftype = file_type(type);
  }
  // In memory the values are the file's little-endian ones (x86).
  const hid_t memtype = strings ? mtype.id : ftype;
  if (kind == 0) {
    Closer lcpl{H5Pcreate(H5P_LINK_CREATE), H5Pclose};
    H5Pset_create_intermediate_group(lcpl.id, 1);
    Closer ds{H5Dcreate2(file, path.c_str(), ftype, space.id, lcpl.id, H5P_DEFAULT, H5P_DEFAULT), H5Dclose};
    if (ds.id >= 0 && count > 0) H5Dwrite(ds.id, memtype, H5S_ALL, H5S_ALL, H5P_DEFAULT, buf);
  } else {
    Closer obj{H5Oopen(file, path.empty() ? "/" : path.c_str(), H5P_DEFAULT), H5Oclose};
    if (obj.id < 0 || attr.empty()) return;
    Closer a{H5Acreate2(obj.id, attr.c_str(), ftype, space.id, H5P_DEFAULT, H5P_DEFAULT), H5Aclose};
    if (a.id >= 0) H5Awrite(a.id, memtype, buf);
  }
}

}  // namespace

bool write_records(const std::uint8_t* data, std::size_t size, const std::string& path) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  Closer file{H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose};
  if (file.id < 0) return false;
  Reader in(data, size);
  for (int records = 0; !in.done() && records < 4096; ++records) {
    const int kind = in.u8() % 3;
    std::string path_in = in.str(in.u8());
    // HDF5 names: no NUL; a leading "/" is added (paths are absolute from the root).
    path_in.erase(std::remove(path_in.begin(), path_in.end(), '\0'), path_in.end());
    const std::string object = path_in.empty() || path_in[0] != '/' ? "/" + path_in : path_in;
    if (kind == 2) {
      Closer lcpl{H5Pcreate(H5P_LINK_CREATE), H5Pclose};
      H5Pset_create_intermediate_group(lcpl.id, 1);
      Closer g{H5Gcreate2(file.id, object.c_str(), lcpl.id, H5P_DEFAULT, H5P_DEFAULT), H5Gclose};
      continue;
    }
    std::string attr;
    if (kind == 1) {
      attr = in.str(in.u8());
      attr.erase(std::remove(attr.begin(), attr.end(), '\0'), attr.end());
    }
    write_object(in, file.id, kind, object == "/" && kind == 0 ? "/x" : object, attr);
  }
  return true;
}

namespace {
std::filesystem::path& scratch_dir() {
  static std::filesystem::path dir;
  return dir;
}
void remove_scratch() {
  std::error_code ec;
  std::filesystem::remove_all(scratch_dir(), ec);
}
}  // namespace

std::string scratch_file(const std::string& name) {
  namespace fs = std::filesystem;
  if (scratch_dir().empty()) {
    std::error_code ec;
    const fs::path base = fs::is_directory("/dev/shm", ec) ? fs::path("/dev/shm") : fs::temp_directory_path();
    scratch_dir() = base / ("moreau_fuzz_" + std::to_string(getpid()));
    fs::create_directories(scratch_dir());
    std::atexit(remove_scratch);
  }
  return (scratch_dir() / name).string();
}

}  // namespace moreau_fuzz
