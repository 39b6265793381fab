#pragma once
// Thin RAII over the HDF5 C API, for kernel/io only (HDF5 stays out of public headers).
#include <hdf5.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace moreau::io::h5 {

class Id {
 public:
  Id() = default;
  Id(hid_t id, herr_t (*close)(hid_t)) : id_(id), close_(close) {}
  Id(Id&& o) noexcept : id_(std::exchange(o.id_, -1)), close_(o.close_) {}
  Id& operator=(Id&& o) noexcept {
    reset();
    id_ = std::exchange(o.id_, -1);
    close_ = o.close_;
    return *this;
  }
  ~Id() { reset(); }
  void reset() {
    if (id_ >= 0 && close_) close_(id_);
    id_ = -1;
  }
  hid_t get() const { return id_; }
  /// Gives up ownership without closing (the caller closes and checks the result).
  void release() { id_ = -1; }
  explicit operator bool() const { return id_ >= 0; }

 private:
  hid_t id_ = -1;
  herr_t (*close_)(hid_t) = nullptr;
};

inline Id file(hid_t id) { return {id, H5Fclose}; }
inline Id group(hid_t id) { return {id, H5Gclose}; }
inline Id dataset(hid_t id) { return {id, H5Dclose}; }
inline Id space(hid_t id) { return {id, H5Sclose}; }
inline Id type(hid_t id) { return {id, H5Tclose}; }
inline Id attribute(hid_t id) { return {id, H5Aclose}; }
inline Id plist(hid_t id) { return {id, H5Pclose}; }

/// Silences HDF5's own error printing: moreau reports its own messages.
inline void quiet() { H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); }

// Writing files that survive a full disk or a file-size limit. HDF5 writes a file's
// metadata when it closes it; when that write fails, H5Fclose fails and leaves the library
// with a half-closed file that crashes it later (HDF5 1.10). So files are built in memory
// (the core driver: closing never writes) and their bytes written out by save(), where a
// failure is an errno with its text and no HDF5 state is left behind. Only files too large
// for memory (the gathered output) are written by HDF5 itself (create_on_disk).

/// A new HDF5 file in memory (the core driver, no backing store; 1.8 format: dense
/// attributes, so a large scene fits in an attribute). Nothing exists on disk until save().
class MemoryFile {
 public:
  /// `name` only labels the file. Check it with operator bool.
  explicit MemoryFile(const std::string& name);
  hid_t get() const { return file_.get(); }
  explicit operator bool() const { return static_cast<bool>(file_); }
  /// Closes the file and writes its bytes to `path` (replacing it). On failure removes
  /// what it wrote of `path` and throws RunError naming `path` and the OS's reason ("No
  /// space left on device", "File too large").
  void save(const std::string& path);
  /// The same through `path`.part renamed into place: a reader sees the old file or the
  /// new one, never half of one; on failure nothing is left.
  void save_atomically(const std::string& path);

  /// The file's final bytes, handed over by the core driver as it closes the file (a
  /// 1.8-format image taken while the file is open still says "open for writing").
  struct Image {
    char* bytes = nullptr;
    bool keep = false;  ///< set just before the close that save() makes
    void* block = nullptr;      ///< the driver's memory while the file is open
    std::size_t capacity = 0;   ///< its size, of which the driver uses a part
    ~Image();
  };

 private:
  std::unique_ptr<Image> image_;  // before file_: outlives the close
  Id file_;
};
/// A new HDF5 file on disk at `path` (same format), closed with close_on_disk().
Id create_on_disk(const std::string& path);
/// Closes a file created with create_on_disk, throwing RunError with the OS's reason if
/// HDF5 could not write everything out. The library is then left in a state where
/// nothing more may be done with that file: callers remove it and move on.
void close_on_disk(Id& file, const std::string& path);
/// An existing small file opened read-only, read into memory in one read (the core driver)
/// rather than block by block as HDF5 needs them: a frame file while the output is gathered.
Id open_whole(const std::string& path);
/// The OS's reason for the last HDF5 call that failed on a system call (the errno text
/// HDF5 records), or "" when it recorded none.
std::string last_os_error();


/// The creation properties of moreau's groups (all but /frames, of one link per frame): their
/// links stay in the group's own header up to 64 of them (HDF5 moves them to a separate
/// heap and index beyond 8 by default). A frame's groups hold 3 to 20 links: building and
/// copying those structures for each was a seventh of a frame's cost, and they made the
/// file a fifth larger. The links are the same, and so is the file format (1.8).
hid_t group_creation();

void write_doubles(hid_t where, const std::string& name, const double* data, hsize_t rows, hsize_t cols);
/// float32 on file: for viewer data, where half the size matters more than the digits.
void write_floats(hid_t where, const std::string& name, const float* data, hsize_t rows, hsize_t cols);
void write_int8(hid_t where, const std::string& name, const std::vector<signed char>& data);
void write_int32(hid_t where, const std::string& name, const int* data, hsize_t rows, hsize_t cols);
void write_strings(hid_t where, const std::string& name, const std::vector<std::string>& strings);
void attribute_double(hid_t where, const std::string& name, double value);
void attribute_long(hid_t where, const std::string& name, long value);
void attribute_string(hid_t where, const std::string& name, const std::string& value);

/// A second name `name` (in `where`) for the object at `target` (HDF5 hard link: no copy).
void link(hid_t where, const std::string& target, const std::string& name);
bool exists(hid_t where, const std::string& path);
/// Reads a dataset of doubles; `shape` gets its dimensions. Throws InputError on faults.
std::vector<double> read_doubles(hid_t where, const std::string& path, std::vector<hsize_t>* shape,
                                 const std::string& file);
/// A dataset's dimensions without reading it (empty if it does not exist).
std::vector<hsize_t> dimensions(hid_t where, const std::string& path);
double read_attribute_double(hid_t where, const std::string& name, const std::string& file, const std::string& path);
std::string read_attribute_string(hid_t where, const std::string& name, const std::string& file, const std::string& path);
std::vector<std::string> read_strings(hid_t where, const std::string& path, const std::string& file);
/// Names of the links in a group, sorted by name.
std::vector<std::string> children(hid_t group);

}  // namespace moreau::io::h5
