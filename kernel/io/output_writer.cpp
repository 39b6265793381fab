#include "output_writer.hpp"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <moreau/error.hpp>

#include <moreau/node_fields.hpp>

#include "display_io.hpp"
#include "field_io.hpp"
#include "force_network.hpp"
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

/// A constant field (output `once`), kept to rewrite the header: a copy of its values at
/// the start, in a one-field set of its own so that write_field writes it.
struct Column {
  std::string set;
  std::unique_ptr<EntitySet> values;
};

/// Group `name` of `where`, created if missing.
h5::Id group_of(hid_t where, const std::string& name) {
  if (h5::exists(where, name)) return h5::group(H5Gopen2(where, name.c_str(), H5P_DEFAULT));
  h5::Id g = h5::group(H5Gcreate2(where, name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
  if (!g) throw RunError("HDF5 write failed: group " + name);
  return g;
}

}  // namespace

struct OutputWriter::Impl {
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
    h5::Id f = create_file(part);
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
    h5::Id g = h5::group(H5Gcreate2(root, "contactors", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
    h5::write_int32(g.get(), "body", body.data(), cs.size(), 0);
    h5::write_int32(g.get(), "node", node.data(), cs.size(), 0);
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
    write_xdmf_file(path, header.dimension, listed_frames, bodies, shapes, layout);
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
    // Its frames are copied as they are: a moreau-output/1 file's would lack the sets'
    // groups of the frames written after them, in a file that says moreau-output/2.
    if (h5::read_attribute_string(src.get(), "format", path, "/") != output_format)
      throw InputError("/", std::string("a file of an earlier format cannot be continued in place: restart from it into a "
                                        "new file (--out NEW.h5), which is ") + output_format,
                       path);
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
      listed.network = h5::exists(fg.get(), "contacts/network");
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
                                    : H5Gcreate2(g.get(), part.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
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
  const std::string name = frame_name(step);
  const std::string file = m.frame_file(step);
  const std::string part = file + ".part";
  h5::Id f = create_file(part);
  if (!f) throw RunError("cannot write frame " + name + " to " + part);
  std::size_t contacts = 0;
  bool with_contacts = false;
  {
    h5::Id g = h5::group(H5Gcreate2(f.get(), "frame", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
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
    // positions) for the force network and for readers.
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
    h5::Id solver = h5::group(H5Gcreate2(g.get(), "solver", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
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
  m.open = false;
  m.publish(true);
  std::error_code ec;
  fs::remove_all(m.folder, ec);
  m.write_xdmf();
}

}  // namespace moreau::io
