#include "output_writer.hpp"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <moreau/error.hpp>

#include "display_io.hpp"
#include "h5.hpp"
#include "xdmf.hpp"

namespace moreau::io {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

std::string frame_name(long step) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%08ld", step);
  return buf;
}

std::string frames_folder(const std::string& h5_path) { return h5_path + ".frames"; }

namespace {

h5::Id create_file(const std::string& path) {
  h5::Id fapl = h5::plist(H5Pcreate(H5P_FILE_ACCESS));
  // 1.8 format: dense attribute storage, so a large scene fits in the `scene` attribute.
  H5Pset_libver_bounds(fapl.get(), H5F_LIBVER_V18, H5F_LIBVER_V18);
  return h5::file(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl.get()));
}

/// Closes a file we wrote, checking that HDF5 could write everything out.
void finish(h5::Id& file, const std::string& path) {
  const hid_t id = file.get();
  file.release();
  if (H5Fclose(id) < 0) throw RunError("cannot finish writing " + path);
}

/// Renames a finished temporary file into place (atomic on POSIX file systems).
void publish_file(const std::string& from, const std::string& to) {
  std::error_code ec;
  fs::rename(from, to, ec);
  if (ec) {
    fs::remove(from, ec);
    throw RunError("cannot rename " + from + " to " + to + ": " + ec.message());
  }
}

/// A per-body dataset of /bodies, kept to rewrite the header.
struct BodyColumn {
  std::string name;
  bool as_int8 = false;
  std::vector<double> values;
  hsize_t components = 1;
};

}  // namespace

struct OutputWriter::Impl {
  std::string path;
  std::string folder;  // one file per frame while the run goes on
  OutputHeader header;
  std::vector<std::string> names;
  std::vector<BodyColumn> columns;
  std::size_t bodies = 0;
  std::vector<XdmfFrame> frames;  // every frame written, in step order
  bool open = true;

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
    bodies = state.bodies();
    for (const auto& f : state.fields()) {
      if (f.spec().output != FieldOutput::bodies) continue;
      BodyColumn c{f.name(), f.spec().as_int8, {}, static_cast<hsize_t>(f.components())};
      c.values.assign(f.data(Depth::begin), f.data(Depth::begin) + f.bodies() * f.components());
      columns.push_back(std::move(c));
    }
  }

  /// The display meshes never change and can be large (tens of MB for 10⁵ spheres): while
  /// the run goes on they sit in their own file in the folder, written once and linked from
  /// OUT.h5 like the frames, so that rewriting the frame list stays cheap.
  std::string display_file() const { return folder + "/display.h5"; }
  void write_display_file() const {
    if (!header.display) return;
    const std::string part = display_file() + ".part";
    h5::Id f = create_file(part);
    if (!f) throw RunError("cannot write " + part);
    write_display_header(f.get(), *header.display);
    finish(f, part);
    publish_file(part, display_file());
  }

  void write_header(hid_t root, bool gather) const {
    h5::attribute_string(root, "format", "moreau-output/1");
    h5::attribute_long(root, "dimension", header.dimension);
    h5::attribute_double(root, "time_step", header.time_step);
    h5::attribute_string(root, "scene", header.scene_text);
    h5::Id g = h5::group(H5Gcreate2(root, "bodies", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
    h5::write_strings(g.get(), "name", names);
    for (const auto& c : columns) {
      if (c.as_int8) {
        std::vector<signed char> v(bodies);
        for (std::size_t i = 0; i < bodies; ++i) v[i] = static_cast<signed char>(c.values[i * c.components]);
        h5::write_int8(g.get(), c.name, v);
      } else {
        h5::write_doubles(g.get(), c.name, c.values.data(), bodies, c.components == 1 ? 0 : c.components);
      }
    }
    g.reset();
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
    std::vector<int> body;
    std::vector<std::string> shape, group;
    std::vector<double> offset, rotation;
    for (const auto& c : cs) {
      body.push_back(c.body);
      shape.push_back(c.shape);
      group.push_back(c.group);
      for (int k = 0; k < d; ++k) offset.push_back(c.offset[k]);
      for (int k = 0; k < (d == 2 ? 1 : 4); ++k) rotation.push_back(c.rotation[k]);
    }
    h5::Id g = h5::group(H5Gcreate2(root, "contactors", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
    h5::write_int32(g.get(), "body", body.data(), cs.size(), 0);
    h5::write_strings(g.get(), "shape", shape);
    h5::write_strings(g.get(), "group", group);
    h5::write_doubles(g.get(), "offset", offset.data(), cs.size(), d);
    if (d == 2) h5::write_doubles(g.get(), "angle", rotation.data(), cs.size(), 0);
    else h5::write_doubles(g.get(), "orientation", rotation.data(), cs.size(), 4);
  }

  /// Writes OUT.h5 anew, with the frames linked (`gather` false) or copied in, and
  /// renames it into place.
  void publish(bool gather) {
    const auto start = Clock::now();
    const std::string part = path + ".part";
    h5::Id f = create_file(part);
    if (!f) throw RunError("cannot write " + part);
    write_header(f.get(), gather);
    h5::Id g = h5::group(H5Gcreate2(f.get(), "frames", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
    for (const auto& fr : frames) {
      const std::string name = frame_name(fr.step);
      herr_t rc;
      if (gather) {
        h5::Id src = h5::file(H5Fopen(frame_file(fr.step).c_str(), H5F_ACC_RDONLY, H5P_DEFAULT));
        rc = src ? H5Ocopy(src.get(), "frame", g.get(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT) : -1;
      } else {
        rc = H5Lcreate_external(frame_link(fr.step).c_str(), "/frame", g.get(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT);
      }
      if (rc < 0) throw RunError("cannot put frame " + name + " into " + part);
    }
    g.reset();
    finish(f, part);
    publish_file(part, path);
    listed = frames.size();
    last_list = Clock::now();
    list_seconds = std::chrono::duration<double>(last_list - start).count();
  }

  void write_xdmf() {
    XdmfDisplay shapes;
    if (header.display)
      shapes = {header.display->vertices(), header.display->cell_count(), header.display->cells.size()};
    // Only the frames OUT.h5 lists: the list is rewritten less often than frames are
    // written, and a description naming a frame the file lacks fails in ParaView.
    const std::vector<XdmfFrame> listed_frames(frames.begin(), frames.begin() + static_cast<long>(listed));
    write_xdmf_file(path, header.dimension, listed_frames, bodies, shapes);
  }
};

OutputWriter::OutputWriter(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}

OutputWriter::~OutputWriter() {
  try {
    close();
  } catch (const std::exception&) {
    // Unwinding from another error: OUT.h5 and its folder still hold every listed frame.
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
  start_folder(path, impl->folder);
  try {
    impl->write_display_file();
    impl->publish(false);
  } catch (const RunError& e) {
    std::error_code ec;
    fs::remove_all(impl->folder, ec);
    throw InputError("", std::string("cannot create the output file: ") + e.what(), path);
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
  {
    h5::Id src = h5::file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT));
    if (!src) throw InputError("", "cannot open the output file to continue it", path);
    if (h5::read_strings(src.get(), "/bodies/name", path) != state.names())
      throw InputError("/bodies/name", "the output file holds other bodies than the scene", path);
    std::error_code ec;
    fs::remove(path + ".part", ec);
    fs::create_directory(impl->folder, ec);
    impl->write_display_file();
    h5::Id frames = h5::group(H5Gopen2(src.get(), "/frames", H5P_DEFAULT));
    if (!frames) throw InputError("/frames", "missing group", path);
    // A gathered file's frames are copied out to the folder; a killed run's are there already.
    for (const auto& name : h5::children(frames.get())) {
      const long step = std::stol(name);
      H5L_info_t info;
      const bool linked = H5Lget_info(frames.get(), name.c_str(), &info, H5P_DEFAULT) >= 0 &&
                          info.type == H5L_TYPE_EXTERNAL;
      if (step > after_step) {
        if (linked) fs::remove(impl->frame_file(step), ec);
        continue;
      }
      h5::Id fg = h5::group(H5Gopen2(frames.get(), name.c_str(), H5P_DEFAULT));
      if (!fg) throw InputError("/frames/" + name, "cannot open the frame", path);
      const double time = h5::read_attribute_double(fg.get(), "time", path, "/frames/" + name);
      std::size_t nc = 0;
      if (h5::exists(fg.get(), "contacts/gap")) {
        std::vector<hsize_t> shape;
        nc = h5::read_doubles(fg.get(), "contacts/gap", &shape, path).size();
      }
      // The viewer description may only name what the frame holds: it may come from a run
      // with other output settings, or from before normal_force was written.
      XdmfFrame listed{step, time, nc};
      listed.normal_force = h5::exists(fg.get(), "contacts/normal_force");
      if (impl->header.display) {
        const auto shape = h5::dimensions(fg.get(), "display/points");
        listed.display = !shape.empty() && shape[0] == impl->header.display->vertices();
      }
      fg.reset();
      if (!linked) {
        const std::string part = impl->frame_file(step) + ".part";
        h5::Id dst = create_file(part);
        if (!dst || H5Ocopy(frames.get(), name.c_str(), dst.get(), "frame", H5P_DEFAULT, H5P_DEFAULT) < 0)
          throw RunError("cannot copy frame " + name + " of " + path + " to " + part);
        finish(dst, part);
        publish_file(part, impl->frame_file(step));
      }
      impl->frames.push_back(listed);
    }
  }
  impl->publish(false);
  return std::unique_ptr<OutputWriter>(new OutputWriter(std::move(impl)));
}

void OutputWriter::write_frame(long step, double time, const State& state, long iterations, double error,
                               const ContactFrame* contacts) {
  Impl& m = *impl_;
  const std::string name = frame_name(step);
  const std::string file = m.frame_file(step);
  const std::string part = file + ".part";
  h5::Id f = create_file(part);
  if (!f) throw RunError("cannot write frame " + name + " to " + part);
  {
    h5::Id g = h5::group(H5Gcreate2(f.get(), "frame", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
    h5::attribute_double(g.get(), "time", time);
    h5::attribute_long(g.get(), "step", step);
    for (const auto& fd : state.fields()) {
      if (fd.spec().output != FieldOutput::frame) continue;
      h5::write_doubles(g.get(), fd.name(), fd.data(Depth::begin), fd.bodies(),
                        fd.components() == 1 ? 0 : fd.components());
    }
    h5::Id solver = h5::group(H5Gcreate2(g.get(), "solver", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
    h5::attribute_long(solver.get(), "iterations", iterations);
    h5::attribute_double(solver.get(), "error", error);
    if (contacts) {
      const int d = m.header.dimension;
      const std::size_t nc = contacts->size();
      h5::Id c = h5::group(H5Gcreate2(g.get(), "contacts", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
      h5::write_int32(c.get(), "bodies", contacts->bodies.data(), nc, 2);
      h5::write_doubles(c.get(), "point", contacts->point.data(), nc, d);
      h5::write_doubles(c.get(), "normal", contacts->normal.data(), nc, d);
      h5::write_doubles(c.get(), "gap", contacts->gap.data(), nc, 0);
      h5::write_doubles(c.get(), "impulse", contacts->impulse.data(), nc, d);
      h5::write_doubles(c.get(), "force", contacts->force.data(), nc, d);
      // The normal force on its own, for viewers that size lines or glyphs by a scalar.
      std::vector<double> normal_force(nc);
      for (std::size_t i = 0; i < nc; ++i) normal_force[i] = contacts->impulse[d * i] / m.header.time_step;
      h5::write_doubles(c.get(), "normal_force", normal_force.data(), nc, 0);
      h5::write_int8(c.get(), "status", contacts->status);
      h5::write_int32(c.get(), "key", contacts->keys.data(), nc, 3);
    }
    if (m.header.display) write_display_frame(g.get(), *m.header.display, state);
  }
  finish(f, part);
  publish_file(part, file);
  if (!m.frames.empty() && m.frames.back().step == step) m.frames.pop_back();  // rewritten (last frame)
  XdmfFrame listed{step, time, contacts ? contacts->size() : 0};
  listed.display = m.header.display != nullptr;
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
  m.open = false;
  m.publish(true);
  std::error_code ec;
  fs::remove_all(m.folder, ec);
  m.write_xdmf();
}

}  // namespace moreau::io
