#include "output_writer.hpp"

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/statvfs.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <cstdio>
#include <filesystem>
#include <moreau/error.hpp>

#include <moreau/contact_fields.hpp>
#include <moreau/node_fields.hpp>

#include "display_io.hpp"
#include "field_io.hpp"
#include "force_network.hpp"
#include "h5.hpp"
#include "output_lock.hpp"
#include "xdmf.hpp"

namespace moreau::io {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

std::string frame_name(long step) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%08ld", step);
  return buf;
}

std::optional<long> frame_step(const std::string& name) {
  if (name.size() < 8 || name.size() > 18) return std::nullopt;
  long step = 0;
  for (char c : name) {
    if (c < '0' || c > '9') return std::nullopt;
    step = 10 * step + (c - '0');
  }
  return step;
}

std::string frames_folder(const std::string& h5_path) { return h5_path + ".frames"; }

std::string legacy_node_set(const State& st) {
  if (st.models().size() != 1) return "";
  const std::string& nodes = st.models()[0].nodes;
  if (st.set(nodes).rows() != st.bodies()) return "";
  for (std::size_t b = 0; b < st.bodies(); ++b) {
    const BodyRows r = st.body(b);
    if (r.nodes != 1 || r.first_node != b) return "";
  }
  return nodes;
}

namespace {

/// A frame, display or list file: built in memory, written out by finish().
h5::MemoryFile create_file(const std::string& path) { return h5::MemoryFile(path); }

/// Writes a file made by create_file to `path`; RunError naming the path and the OS's reason.
void finish(h5::MemoryFile& file, const std::string& path) { file.save(path); }

/// Renames a finished temporary file into place (atomic on POSIX file systems).
void publish_file(const std::string& from, const std::string& to) {
  std::error_code ec;
  fs::rename(from, to, ec);
  if (ec) {
    fs::remove(from, ec);
    throw RunError("cannot rename " + from + " to " + to + ": " + ec.message());
  }
}

/// The largest gathered file built in memory: a quarter of the machine's memory, at most
/// 2 GiB. MOREAU_GATHER_IN_MEMORY_MAX (bytes) overrides it (tests of the on-disk path).
std::uintmax_t memory_gather_limit() {
  if (const char* v = std::getenv("MOREAU_GATHER_IN_MEMORY_MAX")) return std::strtoull(v, nullptr, 10);
  const double memory = static_cast<double>(sysconf(_SC_PHYS_PAGES)) * static_cast<double>(sysconf(_SC_PAGE_SIZE));
  return static_cast<std::uintmax_t>(std::min(memory / 4, 2.0 * (1ull << 30)));
}

std::string megabytes(std::uintmax_t bytes) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f MB", static_cast<double>(bytes) / 1e6);
  return buf;
}

/// Before HDF5 writes a large file itself: the file-size limit and the free space must
/// allow `need` bytes, which are then reserved (fallocate), so that HDF5 meets no failing
/// write. RunError naming the file and what is missing.
void reserve_room(const std::string& part, std::uintmax_t need) {
  struct rlimit limit;
  if (getrlimit(RLIMIT_FSIZE, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY && limit.rlim_cur < need)
    throw RunError("cannot write " + part + ": File too large (it needs about " + megabytes(need) +
                   ", the file-size limit is " + megabytes(limit.rlim_cur) + ")");
  struct statvfs disk;
  const std::string folder = fs::absolute(part).parent_path().string();
  if (statvfs(folder.c_str(), &disk) == 0 && static_cast<std::uintmax_t>(disk.f_bavail) * disk.f_frsize < need)
    throw RunError("cannot write " + part + ": No space left on device (it needs about " + megabytes(need) + ", " +
                   folder + " has " + megabytes(static_cast<std::uintmax_t>(disk.f_bavail) * disk.f_frsize) + " free)");
  const int fd = ::open(part.c_str(), O_WRONLY | O_CLOEXEC);
  if (fd < 0) return;
  const int rc = ::fallocate(fd, FALLOC_FL_KEEP_SIZE, 0, static_cast<off_t>(need));
  const int e = errno;
  ::close(fd);
  if (rc != 0 && e != EOPNOTSUPP && e != ENOSYS)
    throw RunError("cannot write " + part + ": " + std::strerror(e) + " (reserving " + megabytes(need) + ")");
}

/// A constant field (output `once`), kept to rewrite the header: a copy of its values at
/// the start, in a one-field set of its own so that write_field writes it.
struct Column {
  std::string set;
  std::unique_ptr<EntitySet> values;
};

/// Group `name` of `where`, created if missing.
h5::Id group_of(hid_t where, const std::string& name) {
  if (h5::exists(where, name)) return h5::group(H5Gopen2(where, name.c_str(), H5P_DEFAULT));
  h5::Id g = h5::group(H5Gcreate2(where, name.c_str(), H5P_DEFAULT, h5::group_creation(), H5P_DEFAULT));
  if (!g) throw RunError("HDF5 write failed: group " + name);
  return g;
}

}  // namespace

struct OutputWriter::Impl {
  OutputLock lock;  // first taken, last released
  std::string path;
  std::string folder;  // one file per frame while the run goes on
  OutputHeader header;
  std::vector<std::string> names;
  std::vector<ModelInfo> models;
  std::vector<Column> columns;
  std::size_t bodies = 0;
  std::string legacy;  ///< the node set also written at moreau-output/1's places, or ""
  XdmfLayout layout;
  std::vector<XdmfFrame> frames;  // every frame written, in step order
  bool open = true;
  bool failed = false;  // a write failed: nothing more is written (fail())

  Clock::time_point last_list{};
  double list_seconds = 0;  // the cost of the last rewrite of the list
  std::size_t listed = 0;   // frames in the published list
  Clock::time_point last_xdmf = Clock::now();

  std::string frame_file(long step) const { return folder + "/" + frame_name(step) + ".h5"; }
  /// Relative to OUT.h5's folder, so the pair can be moved together.
  std::string frame_link(long step) const {
    return fs::path(folder).filename().string() + "/" + frame_name(step) + ".h5";
  }

  void keep_header(const State& state) {
    names = state.names();
    models = state.models();
    bodies = state.bodies();
    legacy = legacy_node_set(state);
    for (const auto& set : state.sets())
      for (const auto& f : set.fields()) {
        if (f.spec().output != FieldOutput::once) continue;
        Column c{set.name(), std::make_unique<EntitySet>(set.name(), state.dimension())};
        FieldSpec spec = f.spec();
        spec.depths = 1;
        spec.needed = Needed::always;
        c.values->add_rows(f.rows());
        Field& copy = c.values->declare(spec);
        std::copy(f.data(Depth::begin), f.data(Depth::begin) + f.rows() * f.components(), copy.data());
        columns.push_back(std::move(c));
      }
    layout = xdmf_layout(state, header.topologies, legacy);
  }

  /// The display meshes never change and can be large (tens of MB for 10⁵ spheres): while
  /// the run goes on they sit in their own file in the folder, written once and linked from
  /// OUT.h5 like the frames, so that rewriting the frame list stays cheap.
  std::string display_file() const { return folder + "/display.h5"; }
  void write_display_file() const {
    if (!header.display) return;
    const std::string part = display_file() + ".part";
    h5::MemoryFile f = create_file(part);
    if (!f) throw RunError("cannot write " + part);
    write_display_header(f.get(), *header.display);
    finish(f, part);
    publish_file(part, display_file());
  }

  void write_header(hid_t root, bool gather) const {
    h5::attribute_string(root, "format", output_format);
    h5::attribute_long(root, "dimension", header.dimension);
    h5::attribute_double(root, "time_step", header.time_step);
    h5::attribute_string(root, "scene", header.scene_text);
    {
      h5::Id g = group_of(root, sets::bodies);
      h5::write_strings(g.get(), "name", names);
      std::vector<std::string> model_names, node_sets, element_sets;
      for (const auto& m : models) {
        model_names.push_back(m.name);
        node_sets.push_back(m.nodes);
        element_sets.push_back(m.elements);
      }
      h5::Id mg = group_of(root, "models");
      h5::write_strings(mg.get(), "name", model_names);
      h5::write_strings(mg.get(), "nodes", node_sets);
      h5::write_strings(mg.get(), "elements", element_sets);
      std::vector<int> dofs;
      for (const auto& m : models) dofs.push_back(m.node_dofs);
      h5::write_int32(mg.get(), "node_dofs", dofs.data(), dofs.size(), 0);
    }
    // Every set's constant fields in /<set>/ (the bodies set's in /bodies), and for a
    // rigid-only scene the node set's also in /bodies, as moreau-output/1 had them.
    for (const auto& c : columns) {
      h5::Id g = group_of(root, c.set);
      const Field& f = c.values->fields().front();
      write_field(g.get(), f.name(), f, Depth::begin);
      if (c.set == legacy && f.name() != body_fields::body)
        h5::link(root, "/" + c.set + "/" + f.name(), std::string(sets::bodies) + "/" + f.name());
    }
    for (const auto& t : header.topologies) {
      h5::Id g = group_of(root, t.elements);
      h5::write_int32(g.get(), "cells", t.cells.data(), t.cells.size(), 0);
      h5::attribute_long(g.get(), "cells", static_cast<long>(t.count));
      h5::attribute_string(g.get(), "nodes", t.nodes);
    }
    write_contactors(root);
    if (!header.display) return;
    if (gather) {
      write_display_header(root, *header.display);
    } else {
      const std::string link = fs::path(folder).filename().string() + "/display.h5";
      if (H5Lcreate_external(link.c_str(), "/display", root, "display", H5P_DEFAULT, H5P_DEFAULT) < 0)
        throw RunError("cannot link /display to " + link);
    }
  }

  /// `/contactors`: body, shape, group and placement of each contactor, so that a reader
  /// can place the shapes of a cluster (world = body pose ∘ placement).
  void write_contactors(hid_t root) const {
    const auto& cs = header.contactors;
    if (cs.empty()) return;
    const int d = header.dimension;
    std::vector<int> body, node;
    std::vector<std::string> shape, group;
    std::vector<double> offset, rotation;
    for (const auto& c : cs) {
      body.push_back(c.body);
      node.push_back(c.local_node);
      shape.push_back(c.shape);
      group.push_back(c.group);
      for (int k = 0; k < d; ++k) offset.push_back(c.offset[k]);
      for (int k = 0; k < (d == 2 ? 1 : 4); ++k) rotation.push_back(c.rotation[k]);
    }
    h5::Id g = h5::group(H5Gcreate2(root, "contactors", H5P_DEFAULT, h5::group_creation(), H5P_DEFAULT));
    h5::write_int32(g.get(), "body", body.data(), cs.size(), 0);
    h5::write_int32(g.get(), "node", node.data(), cs.size(), 0);
    h5::write_strings(g.get(), "shape", shape);
    h5::write_strings(g.get(), "group", group);
    h5::write_doubles(g.get(), "offset", offset.data(), cs.size(), d);
    if (d == 2) h5::write_doubles(g.get(), "angle", rotation.data(), cs.size(), 0);
    else h5::write_doubles(g.get(), "orientation", rotation.data(), cs.size(), 4);
  }

  /// Writes OUT.h5 anew, with the frames linked (`gather` false) or copied in, and
  /// renames it into place. On failure the temporary file is removed: OUT.h5 stays as it was.
  void publish(bool gather) {
    const std::string part = path + ".part";
    try {
      write_list(gather, part);
    } catch (...) {
      std::error_code ec;
      fs::remove(part, ec);
      throw;
    }
  }

  void write_list(bool gather, const std::string& part) {
    const auto start = Clock::now();
    // Built in memory and written with write(2) when it fits in memory (HDF5 1.10 crashes
    // when a write fails during H5Ocopy or H5Fclose); a gathered file too large for that is
    // written by HDF5 once the room it needs is checked and reserved.
    const std::uintmax_t need = gather ? gathered_size() : 0;
    if (gather && need > memory_gather_limit()) {
      h5::Id f = h5::create_on_disk(part);
      if (!f) throw RunError("cannot write " + part + ": " + h5::last_os_error());
      reserve_room(part, need);
      write_list_into(f.get(), gather, part);
      h5::close_on_disk(f, part);
    } else {
      h5::MemoryFile f = create_file(part);
      if (!f) throw RunError("cannot create " + part + " in memory");
      write_list_into(f.get(), gather, part);
      finish(f, part);
    }
    publish_file(part, path);
    listed = frames.size();
    last_list = Clock::now();
    list_seconds = std::chrono::duration<double>(last_list - start).count();
  }

  /// An upper bound of the gathered file's size: the frame files, the display file, and
  /// room for the header.
  std::uintmax_t gathered_size() const {
    std::error_code ec;
    std::uintmax_t total = 1 << 20;
    for (const auto& fr : frames) {
      const auto n = fs::file_size(frame_file(fr.step), ec);
      if (!ec) total += n;
    }
    if (header.display) {
      const auto n = fs::file_size(display_file(), ec);
      if (!ec) total += n;
    }
    return total + header.scene_text.size();
  }

  /// The header and the frames (linked, or copied in when `gather`) under `root`.
  void write_list_into(hid_t root, bool gather, const std::string& part) const {
    write_header(root, gather);
    h5::Id g = h5::group(H5Gcreate2(root, "frames", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
    for (const auto& fr : frames) {
      const std::string name = frame_name(fr.step);
      herr_t rc;
      if (gather) {
        // Read in one go: block by block (pread per metadata block) was a sixth of the gather.
        h5::Id src = h5::open_whole(frame_file(fr.step));
        rc = src ? H5Ocopy(src.get(), "frame", g.get(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT) : -1;
      } else {
        rc = H5Lcreate_external(frame_link(fr.step).c_str(), "/frame", g.get(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT);
      }
      if (rc < 0) {
        const std::string why = h5::last_os_error();
        throw RunError("cannot put frame " + name + " into " + part + (why.empty() ? "" : ": " + why));
      }
    }
  }

  /// Continues the file at `path` after frame `after_step` (append()).
  void reopen(long after_step);

  /// Lists frame `name` (step `step`) of the open output file `src_path` (group `frames`),
  /// copying it into the folder when `copy` (else it is there already).
  void adopt(hid_t frames_group, const std::string& name, long step, const std::string& src_path, bool copy) {
    const std::string where = "/frames/" + name;
    h5::Id fg = h5::group(H5Gopen2(frames_group, name.c_str(), H5P_DEFAULT));
    if (!fg) throw InputError(where, "cannot open the frame", src_path);
    const double time = h5::read_attribute_double(fg.get(), "time", src_path, where);
    std::size_t nc = 0;
    if (h5::exists(fg.get(), "contacts/gap")) {
      std::vector<hsize_t> shape;
      nc = h5::read_doubles(fg.get(), "contacts/gap", &shape, src_path).size();
    }
    // The viewer description may only name what the frame holds: it may come from a run
    // with other output settings, or from before normal_force was written.
    XdmfFrame listed{step, time, nc};
    listed.normal_force = h5::exists(fg.get(), "contacts/normal_force");
    listed.network = h5::exists(fg.get(), "contacts/network");
    if (header.display) {
      const auto shape = h5::dimensions(fg.get(), "display/points");
      listed.display = !shape.empty() && shape[0] == header.display->vertices();
    }
    fg.reset();
    if (copy) {
      const std::string part = frame_file(step) + ".part";
      h5::MemoryFile dst = create_file(part);
      if (!dst) throw RunError("cannot create " + part + " in memory");
      if (H5Ocopy(frames_group, name.c_str(), dst.get(), "frame", H5P_DEFAULT, H5P_DEFAULT) < 0)
        throw InputError(where, "cannot copy the frame", src_path);
      finish(dst, part);
      publish_file(part, frame_file(step));
    }
    frames.push_back(listed);
  }

  /// A write failed (a full disk, a file-size limit): stop writing, leave what a killed run
  /// leaves — OUT.h5 listing every complete frame, with OUT.h5.frames/ beside it, which
  /// read as one file and which `--restart` continues — and no temporary file. Rethrows
  /// with the way to recover.
  [[noreturn]] void fail(const std::exception& e) {
    failed = true;
    open = false;
    std::error_code ec;
    fs::remove(path + ".part", ec);
    for (const auto& entry : fs::directory_iterator(folder, ec))
      if (entry.path().extension() == ".part") fs::remove(entry.path(), ec);
    try {
      if (listed < frames.size()) publish(false);  // small: may still fit
    } catch (const std::exception&) {
    }
    try {
      write_xdmf();
    } catch (const std::exception&) {
    }
    const long last = listed ? frames[listed - 1].step : -1;
    std::string what = e.what();
    if (last >= 0)
      what += "; the frames up to step " + std::to_string(last) + " are complete in " + path + " with " + folder +
              "/ beside it (read as one file, like the output of a killed run); once there is room, `moreau run SCENE "
              "--restart " + path + " --out " + path + "` continues the run and gathers them into " + path;
    throw RunError(what);
  }

  void write_xdmf() {
    XdmfDisplay shapes;
    if (header.display)
      shapes = {header.display->vertices(), header.display->cell_count(), header.display->cells.size()};
    // Only the frames OUT.h5 lists: the list is rewritten less often than frames are
    // written, and a description naming a frame the file lacks fails in ParaView.
    const std::vector<XdmfFrame> listed_frames(frames.begin(), frames.begin() + static_cast<long>(listed));
    write_xdmf_file(path, header.dimension, listed_frames, bodies, shapes, layout);
  }
};

OutputWriter::OutputWriter(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}

OutputWriter::~OutputWriter() {
  try {
    close();
  } catch (const std::exception&) {
    // Unwinding from another error: OUT.h5 and its folder still hold every listed frame
    // (fail() said so when the error was the writer's).
  }
}

const std::string& OutputWriter::path() const { return impl_->path; }

namespace {

/// Starts the frames folder, naming the reason when the output path cannot be written.
void start_folder(const std::string& path, const std::string& folder) {
  std::error_code ec;
  fs::remove(path + ".part", ec);
  fs::remove_all(folder, ec);  // left by an earlier killed run
  if (fs::create_directory(folder, ec) && !ec) return;
  const fs::path parent = fs::absolute(path, ec).parent_path();
  const std::string why = !fs::is_directory(parent, ec) ? "its folder " + parent.string() + " does not exist"
                                                         : "the folder is not writable";
  throw InputError("", "cannot create the output file: " + why, path);
}

}  // namespace

std::unique_ptr<OutputWriter> OutputWriter::create(const std::string& path, const OutputHeader& header,
                                                   const State& state) {
  h5::quiet();
  auto impl = std::make_unique<Impl>();
  impl->path = path;
  impl->folder = frames_folder(path);
  impl->header = header;
  impl->keep_header(state);
  impl->lock = OutputLock::acquire(path);
  start_folder(path, impl->folder);
  try {
    impl->write_display_file();
    impl->publish(false);
  } catch (const RunError& e) {
    // A full disk at the start: nothing left behind (a previous OUT.h5 stays as it was).
    std::error_code ec;
    fs::remove_all(impl->folder, ec);
    throw RunError(std::string("cannot create the output file: ") + e.what());
  }
  return std::unique_ptr<OutputWriter>(new OutputWriter(std::move(impl)));
}

std::unique_ptr<OutputWriter> OutputWriter::append(const std::string& path, const OutputHeader& header,
                                                   const State& state, long after_step) {
  h5::quiet();
  auto impl = std::make_unique<Impl>();
  impl->path = path;
  impl->folder = frames_folder(path);
  impl->header = header;
  impl->keep_header(state);
  impl->lock = OutputLock::acquire(path);
  std::error_code ec;
  const bool had_folder = fs::is_directory(impl->folder, ec);
  try {
    impl->reopen(after_step);
  } catch (...) {
    // The file stays as it was: a folder made here goes, a killed run's stays.
    fs::remove(path + ".part", ec);
    if (!had_folder) fs::remove_all(impl->folder, ec);
    throw;
  }
  return std::unique_ptr<OutputWriter>(new OutputWriter(std::move(impl)));
}

void OutputWriter::Impl::reopen(long after_step) {
  {
    h5::Id src = h5::file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT));
    if (!src) throw InputError("", "cannot open the output file to continue it", path);
    if (h5::read_strings(src.get(), "/bodies/name", path) != names)
      throw InputError("/bodies/name", "the output file holds other bodies than the scene", path);
    // Its frames are copied as they are: a moreau-output/1 file's would lack the sets'
    // groups of the frames written after them, in a file that says moreau-output/2.
    if (h5::read_attribute_string(src.get(), "format", path, "/") != output_format)
      throw InputError("/", std::string("a file of an earlier format cannot be continued in place: restart from it into a "
                                        "new file (--out NEW.h5), which is ") + output_format,
                       path);
    // Its frames are copied as they are: a moreau-output/1 file's would lack the sets'
    // groups of the frames written after them, in a file that says moreau-output/2.
    if (h5::read_attribute_string(src.get(), "format", path, "/") != output_format)
      throw InputError("/", std::string("a file of an earlier format cannot be continued in place: restart from it into a "
                                        "new file (--out NEW.h5), which is ") + output_format,
                       path);
    std::error_code ec;
    fs::remove(path + ".part", ec);
    fs::create_directory(folder, ec);
    write_display_file();
    h5::Id list = h5::group(H5Gopen2(src.get(), "/frames", H5P_DEFAULT));
    if (!list) throw InputError("/frames", "missing group", path);
    // A gathered file's frames are copied out to the folder; a killed run's are there already.
    for (const auto& name : h5::children(list.get())) {
      const std::optional<long> parsed = frame_step(name);
      if (!parsed) throw InputError("/frames/" + name, "not a frame (frames are named by their step, 8 digits)", path);
      const long step = *parsed;
      H5L_info_t info;
      const bool linked = H5Lget_info(list.get(), name.c_str(), &info, H5P_DEFAULT) >= 0 &&
                          info.type == H5L_TYPE_EXTERNAL;
      if (step > after_step) {
        if (linked) fs::remove(frame_file(step), ec);
        continue;
      }
      // A killed run's frame is in the folder already (unless the link points elsewhere).
      adopt(list.get(), name, step, path, !(linked && fs::exists(frame_file(step), ec)));
    }
  }
  publish(false);
}

bool OutputWriter::copy_first_frame(const std::string& source, long step) {
  Impl& m = *impl_;
  h5::Id src = h5::file(H5Fopen(source.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT));
  if (!src) throw InputError("", "cannot open as an HDF5 output file", source);
  // A frame of an earlier format would mix layouts in this file: the run writes it anew.
  if (h5::read_attribute_string(src.get(), "format", source, "/") != output_format) return false;
  h5::Id list = h5::group(H5Gopen2(src.get(), "/frames", H5P_DEFAULT));
  if (!list) throw InputError("/frames", "missing group", source);
  try {
    m.adopt(list.get(), frame_name(step), step, source, true);
    m.publish(false);
  } catch (const RunError& e) {
    m.fail(e);
  }
  return true;
}

namespace {

/// Opens or creates each group of `path` ("a/b/c") under `where`.
h5::Id make_groups(hid_t where, const std::string& path) {
  h5::Id g = h5::group(H5Gopen2(where, ".", H5P_DEFAULT));
  std::size_t start = 0;
  while (start < path.size()) {
    std::size_t end = path.find('/', start);
    if (end == std::string::npos) end = path.size();
    const std::string part = path.substr(start, end - start);
    if (!part.empty()) {
      const bool there = H5Lexists(g.get(), part.c_str(), H5P_DEFAULT) > 0;
      h5::Id next = h5::group(there ? H5Gopen2(g.get(), part.c_str(), H5P_DEFAULT)
                                    : H5Gcreate2(g.get(), part.c_str(), H5P_DEFAULT, h5::group_creation(), H5P_DEFAULT));
      if (!next) throw RunError("HDF5 write failed: group " + path);
      g = std::move(next);
    }
    start = end + 1;
  }
  return g;
}

/// A frame's extra groups (analyses): numbers of any rank, or strings.
void write_frame_group(hid_t frame, const FrameGroup& group) {
  h5::Id g = make_groups(frame, group.path);
  for (const auto& [key, value] : group.attributes) h5::attribute_string(g.get(), key, value);
  for (const auto& ds : group.datasets) {
    const auto slash = ds.name.rfind('/');
    h5::Id parent = slash == std::string::npos ? make_groups(g.get(), "") : make_groups(g.get(), ds.name.substr(0, slash));
    const std::string leaf = slash == std::string::npos ? ds.name : ds.name.substr(slash + 1);
    if (!ds.strings.empty()) {
      h5::write_strings(parent.get(), leaf, ds.strings);
      continue;
    }
    std::vector<hsize_t> dims(ds.shape.begin(), ds.shape.end());
    hsize_t n = 1;
    for (hsize_t x : dims) n *= x;
    if (n != ds.values.size())
      throw std::logic_error("frame dataset " + group.path + "/" + ds.name + ": shape does not match its values");
    h5::Id sp = h5::space(dims.empty() ? H5Screate(H5S_SCALAR) : H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr));
    h5::Id d = h5::dataset(H5Dcreate2(parent.get(), leaf.c_str(), H5T_IEEE_F64LE, sp.get(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
    if (!d) throw RunError("HDF5 write failed: dataset " + group.path + "/" + ds.name);
    if (n > 0 && H5Dwrite(d.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, ds.values.data()) < 0)
      throw RunError("HDF5 write failed: dataset " + group.path + "/" + ds.name);
    if (!ds.units.empty()) h5::attribute_string(d.get(), "units", ds.units);
  }
}

}  // namespace

void OutputWriter::write_frame(long step, double time, const State& state, long iterations, double error,
                               const std::vector<FrameGroup>& extra) {
  Impl& m = *impl_;
  if (m.failed) throw RunError("the output file " + m.path + " could not be written");
  try {
    write_frame_file(step, time, state, iterations, error, extra);
  } catch (const std::exception& e) {
    m.fail(e);
  }
}

void OutputWriter::write_frame_file(long step, double time, const State& state, long iterations, double error,
                                    const std::vector<FrameGroup>& extra) {
  Impl& m = *impl_;
  const std::string name = frame_name(step);
  const std::string file = m.frame_file(step);
  const std::string part = file + ".part";
  h5::MemoryFile f = create_file(part);
  if (!f) throw RunError("cannot write frame " + name + " to " + part);
  std::size_t contacts = 0;
  bool with_contacts = false;
  {
    h5::Id g = h5::group(H5Gcreate2(f.get(), "frame", H5P_DEFAULT, h5::group_creation(), H5P_DEFAULT));
    h5::attribute_double(g.get(), "time", time);
    h5::attribute_long(g.get(), "step", step);
    // Every set's frame fields in <set>/ (the end-of-step values: depths were swapped).
    for (const auto& set : state.sets()) {
      h5::Id sg;
      for (const auto& fd : set.fields()) {
        if (fd.spec().output != FieldOutput::frame) continue;
        if (!sg) sg = group_of(g.get(), set.name());
        write_field(sg.get(), fd.name(), fd, Depth::begin);
        if (set.name() == m.legacy) h5::link(g.get(), set.name() + "/" + fd.name(), fd.name());
      }
      if (set.name() == sets::contacts) {
        with_contacts = true;
        contacts = set.rows();
      }
    }
    // The viewer's force network: node, contact point, node (force_network.hpp).
    if (with_contacts) {
      std::vector<float> network;
      force_network_points(state, m.header.contactors, Depth::begin, network);
      h5::Id cg = group_of(g.get(), sets::contacts);
      h5::write_floats(cg.get(), "network", network.data(), 3 * contacts, state.dimension());
    }
    // Without the rigid-only layout, a reference point per body (the mean of its nodes'
    // positions) for readers.
    if (m.legacy.empty()) {
      const int d = state.dimension();
      std::vector<double> x(state.bodies() * d, 0.0);
      for (std::size_t b = 0; b < state.bodies(); ++b) {
        if (!state.has_node_field(b, node_fields::position)) continue;
        const auto p = state.node_values(b, node_fields::position, Depth::begin);
        const std::size_t n = p.size() / d;
        for (std::size_t i = 0; i < n; ++i)
          for (int k = 0; k < d; ++k) x[b * d + k] += p[i * d + k] / static_cast<double>(n);
      }
      h5::Id bg = group_of(g.get(), sets::bodies);
      h5::write_doubles(bg.get(), node_fields::position, x.data(), state.bodies(), d);
    }
    h5::Id solver = group_of(g.get(), sets::solver);  // may hold the solver's own state already
    h5::attribute_long(solver.get(), "iterations", iterations);
    h5::attribute_double(solver.get(), "error", error);
    if (m.header.display) write_display_frame(g.get(), *m.header.display, state);
    for (const auto& group : extra) write_frame_group(g.get(), group);
  }
  finish(f, part);
  publish_file(part, file);
  if (!m.frames.empty() && m.frames.back().step == step) m.frames.pop_back();  // rewritten (last frame)
  XdmfFrame listed{step, time, with_contacts ? contacts : 0};
  listed.display = m.header.display != nullptr;
  listed.network = with_contacts;
  m.frames.push_back(listed);
  // The list costs O(frames) to rewrite: keep it under a tenth of the time between rewrites.
  const auto now = Clock::now();
  if (m.listed == 0 || std::chrono::duration<double>(now - m.last_list).count() >= 10 * m.list_seconds) m.publish(false);
  // Same for the viewer description: when the frame count doubles or 30 s after the last.
  const std::size_t n = m.frames.size();
  if ((n & (n - 1)) == 0 || now - m.last_xdmf > std::chrono::seconds(30)) {
    m.write_xdmf();
    m.last_xdmf = now;
  }
}

void OutputWriter::close() {
  Impl& m = *impl_;
  if (!m.open) return;
  try {
    m.publish(true);
  } catch (const std::exception& e) {
    m.fail(e);
  }
  m.open = false;
  std::error_code ec;
  fs::remove_all(m.folder, ec);
  m.write_xdmf();
}

}  // namespace moreau::io
