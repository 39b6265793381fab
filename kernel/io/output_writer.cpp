#include "output_writer.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <moreau/error.hpp>

#include "h5.hpp"
#include "xdmf.hpp"

namespace moreau::io {

namespace fs = std::filesystem;

std::string frame_name(long step) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%08ld", step);
  return buf;
}

struct OutputWriter::Impl {
  std::string path;
  OutputHeader header;
  h5::Id file;
  std::vector<XdmfFrame> frames;  // for the viewer description
  std::vector<std::string> frame_fields;

  void configure_cache() {
    // A fixed 16 MiB metadata cache that keeps no minimum of clean space: between two
    // flushes a frame dirties far less than that, so dirty metadata reaches the disk only
    // at the explicit flushes (see the header); clean entries are evicted as needed, so
    // memory stays bounded over long runs.
    H5AC_cache_config_t cfg;
    cfg.version = H5AC__CURR_CACHE_CONFIG_VERSION;
    if (H5Fget_mdc_config(file.get(), &cfg) < 0) return;
    cfg.incr_mode = H5C_incr__off;
    cfg.flash_incr_mode = H5C_flash_incr__off;
    cfg.decr_mode = H5C_decr__off;
    cfg.set_initial_size = true;
    cfg.initial_size = 16 * 1024 * 1024;
    cfg.max_size = 16 * 1024 * 1024;
    cfg.min_size = 16 * 1024 * 1024;
    cfg.min_clean_fraction = 0.0;
    H5Fset_mdc_config(file.get(), &cfg);
  }

  void flush() {
    if (H5Fflush(file.get(), H5F_SCOPE_GLOBAL) < 0) throw RunError("cannot flush the output file " + path);
  }

  std::size_t bodies = 0;
  std::chrono::steady_clock::time_point last_xdmf = std::chrono::steady_clock::now();
  void write_xdmf() { write_xdmf_file(path, header.dimension, frames, bodies); }
};

static h5::Id access_plist() {
  h5::Id fapl = h5::plist(H5Pcreate(H5P_FILE_ACCESS));
  // 1.8 format: dense attribute storage (a large scene fits in the `scene` attribute), and
  // no 1.10 superblock status flags.
  H5Pset_libver_bounds(fapl.get(), H5F_LIBVER_V18, H5F_LIBVER_V18);
  return fapl;
}

OutputWriter::OutputWriter(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
OutputWriter::~OutputWriter() = default;

const std::string& OutputWriter::path() const { return impl_->path; }

std::unique_ptr<OutputWriter> OutputWriter::create(const std::string& path, const OutputHeader& header,
                                                   const State& state) {
  h5::quiet();
  auto impl = std::make_unique<Impl>();
  impl->path = path;
  impl->header = header;
  impl->bodies = state.bodies();
  h5::Id fapl = access_plist();
  impl->file = h5::file(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl.get()));
  if (!impl->file) {
    std::error_code ec;
    const fs::path parent = fs::absolute(path, ec).parent_path();
    std::string why = !fs::is_directory(parent, ec) ? "its folder " + parent.string() + " does not exist"
                                                     : "the folder is not writable or the file is in use";
    throw InputError("", "cannot create the output file: " + why, path);
  }
  impl->configure_cache();
  hid_t root = impl->file.get();
  h5::attribute_string(root, "format", "moreau-output/1");
  h5::attribute_long(root, "dimension", header.dimension);
  h5::attribute_double(root, "time_step", header.time_step);
  h5::attribute_string(root, "scene", header.scene_text);
  {
    h5::Id bodies = h5::group(H5Gcreate2(root, "bodies", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
    h5::write_strings(bodies.get(), "name", state.names());
    for (const auto& f : state.fields()) {
      if (f.spec().output != FieldOutput::bodies) continue;
      if (f.spec().as_int8) {
        std::vector<signed char> v(f.bodies());
        for (std::size_t i = 0; i < v.size(); ++i) v[i] = static_cast<signed char>(f.data(Depth::begin)[i * f.components()]);
        h5::write_int8(bodies.get(), f.name(), v);
      } else {
        h5::write_doubles(bodies.get(), f.name(), f.data(Depth::begin), f.bodies(), f.components() == 1 ? 0 : f.components());
      }
    }
  }
  h5::Id frames = h5::group(H5Gcreate2(root, "frames", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
  impl->flush();
  return std::unique_ptr<OutputWriter>(new OutputWriter(std::move(impl)));
}

std::unique_ptr<OutputWriter> OutputWriter::append(const std::string& path, const OutputHeader& header,
                                                   const State& state, long after_step) {
  h5::quiet();
  auto impl = std::make_unique<Impl>();
  impl->path = path;
  impl->header = header;
  impl->bodies = state.bodies();
  h5::Id fapl = access_plist();
  impl->file = h5::file(H5Fopen(path.c_str(), H5F_ACC_RDWR, fapl.get()));
  if (!impl->file) throw InputError("", "cannot open the output file for writing", path);
  impl->configure_cache();
  const auto names = h5::read_strings(impl->file.get(), "/bodies/name", path);
  if (names != state.names())
    throw InputError("/bodies/name", "the output file holds other bodies than the scene", path);
  h5::Id frames = h5::group(H5Gopen2(impl->file.get(), "/frames", H5P_DEFAULT));
  for (const auto& name : h5::children(frames.get())) {
    const long step = std::stol(name);
    if (step > after_step) H5Ldelete(frames.get(), name.c_str(), H5P_DEFAULT);
    else impl->frames.push_back(XdmfFrame{step, step * header.time_step, 0});
  }
  impl->flush();
  return std::unique_ptr<OutputWriter>(new OutputWriter(std::move(impl)));
}

void OutputWriter::write_frame(long step, double time, const State& state, long iterations, double error,
                               const ContactFrame* contacts) {
  Impl& m = *impl_;
  const std::string name = frame_name(step);
  hid_t root = m.file.get();
  // Build the frame as an anonymous group, flush, then link it: it appears complete or not at all.
  h5::Id g = h5::group(H5Gcreate_anon(root, H5P_DEFAULT, H5P_DEFAULT));
  if (!g) throw RunError("cannot write frame " + name + " to " + m.path);
  h5::attribute_double(g.get(), "time", time);
  h5::attribute_long(g.get(), "step", step);
  for (const auto& f : state.fields()) {
    if (f.spec().output != FieldOutput::frame) continue;
    h5::write_doubles(g.get(), f.name(), f.data(Depth::begin), f.bodies(), f.components() == 1 ? 0 : f.components());
  }
  const int d = m.header.dimension;
  std::size_t nc = 0;
  {
    h5::Id solver = h5::group(H5Gcreate2(g.get(), "solver", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
    h5::attribute_long(solver.get(), "iterations", iterations);
    h5::attribute_double(solver.get(), "error", error);
  }
  if (contacts) {
    nc = contacts->size();
    h5::Id c = h5::group(H5Gcreate2(g.get(), "contacts", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
    h5::write_int32(c.get(), "bodies", contacts->bodies.data(), nc, 2);
    h5::write_doubles(c.get(), "point", contacts->point.data(), nc, d);
    h5::write_doubles(c.get(), "normal", contacts->normal.data(), nc, d);
    h5::write_doubles(c.get(), "gap", contacts->gap.data(), nc, 0);
    h5::write_doubles(c.get(), "impulse", contacts->impulse.data(), nc, d);
    h5::write_doubles(c.get(), "force", contacts->force.data(), nc, d);
    h5::write_int8(c.get(), "status", contacts->status);
    h5::write_int32(c.get(), "key", contacts->keys.data(), nc, 3);
  }
  m.flush();
  if (H5Lexists(root, ("/frames/" + name).c_str(), H5P_DEFAULT) > 0)
    H5Ldelete(root, ("/frames/" + name).c_str(), H5P_DEFAULT);
  if (H5Olink(g.get(), root, ("/frames/" + name).c_str(), H5P_DEFAULT, H5P_DEFAULT) < 0)
    throw RunError("cannot link frame " + name + " in " + m.path);
  m.flush();
  m.frames.push_back(XdmfFrame{step, time, nc});
  // The viewer description lists every frame, so rewriting it costs O(frames): it is
  // rewritten when the frame count doubles or 30 s after the last rewrite, and at close.
  const std::size_t n = m.frames.size();
  const auto now = std::chrono::steady_clock::now();
  if ((n & (n - 1)) == 0 || now - m.last_xdmf > std::chrono::seconds(30)) {
    m.write_xdmf();
    m.last_xdmf = now;
  }
}

void OutputWriter::close() {
  if (!impl_->file) return;
  impl_->flush();
  impl_->write_xdmf();
  impl_->file.reset();
}

}  // namespace moreau::io
