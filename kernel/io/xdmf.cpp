#include "xdmf.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <moreau/node_fields.hpp>
#include <sstream>

#include "output_writer.hpp"

namespace moreau::io {

namespace fs = std::filesystem;

XdmfLayout xdmf_layout(const State& st, const std::vector<SetTopology>& topologies, const std::string& legacy) {
  XdmfLayout out;
  out.legacy = !legacy.empty();
  if (const EntitySet* contacts = st.find_set(sets::contacts))
    for (const auto& f : contacts->fields()) {
      static const char* drawn[] = {"bodies", "key", "point", "normal", "gap", "impulse", "force", "normal_force", "status"};
      if (f.spec().output != FieldOutput::frame || std::find(std::begin(drawn), std::end(drawn), f.name()) != std::end(drawn))
        continue;
      out.contact_fields.push_back({f.name(), f.components(), f.spec().file});
    }
  if (out.legacy) return out;
  auto frame_fields = [](const EntitySet& set) {
    std::vector<std::pair<std::string, int>> v;
    for (const auto& f : set.fields())
      if (f.spec().output == FieldOutput::frame) v.emplace_back(f.name(), f.components());
    return v;
  };
  for (const auto& m : st.models()) {
    const EntitySet& nodes = st.set(m.nodes);
    const Field* x = nodes.find(node_fields::position);
    if (!x || x->spec().output != FieldOutput::frame) continue;  // nothing to place them
    XdmfSet s;
    s.name = m.name;
    s.nodes = m.nodes;
    s.rows = nodes.rows();
    s.node_fields = frame_fields(nodes);
    for (const auto& t : topologies)
      if (t.elements == m.elements && t.count > 0) {
        s.elements = t.elements;
        s.cells = t.count;
        s.connectivity = t.cells.size();
        s.element_fields = frame_fields(st.set(m.elements));
      }
    out.sets.push_back(std::move(s));
  }
  return out;
}

std::string xdmf_path(const std::string& h5_path) {
  fs::path p(h5_path);
  p.replace_extension(".xmf");
  return p.string();
}

namespace {

std::string frame_path(long step) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "/frames/%08ld", step);
  return buf;
}

/// An HDF5 array's type as XDMF spells it.
struct Type {
  const char* number;
  int precision;
};
constexpr Type f64{"Float", 8}, f32{"Float", 4}, i32{"Int", 4}, i8{"Char", 1};

void item(std::ostream& os, const std::string& file, const std::string& path, std::size_t rows, int cols,
          Type type = f64) {
  os << "<DataItem Dimensions=\"" << rows;
  if (cols > 0) os << " " << cols;
  os << "\" NumberType=\"" << type.number << "\" Precision=\"" << type.precision << "\" Format=\"HDF\">" << file
     << ":" << path << "</DataItem>";
}

void attribute(std::ostream& os, const char* name, const char* kind, const std::string& file, const std::string& path,
               std::size_t rows, int cols, Type type = f64, const char* center = "Node") {
  os << "      <Attribute Name=\"" << name << "\" AttributeType=\"" << kind << "\" Center=\"" << center << "\">";
  item(os, file, path, rows, cols, type);
  os << "</Attribute>\n";
}

void grid_start(std::ostream& os, const char* name, const XdmfFrame& f) {
  os << "   <Grid Name=\"" << name << " " << f.step << "\" GridType=\"Uniform\">\n      <Time Value=\"" << f.time
     << "\"/>\n";
}

struct Writer {
  std::ostream& os;
  std::string file;  // the HDF5 file, relative: the pair can be moved together
  int d;
  const char* geometry;
  std::size_t nb;
  const XdmfLayout& layout;

  /// Where the frames hold a point per body: the positions (rigid-only scenes) or the
  /// bodies' reference points.
  std::string body_points(long step) const {
    return frame_path(step) + (layout.legacy ? "/position" : "/bodies/position");
  }

  /// A frame without contacts still has its grid (so every collection spans the same
  /// times), with no cells. Its points are the bodies' (any existing array does): an
  /// empty inline DataItem aborts ParaView's Xdmf3 readers ("'Content' not found").
  void empty_grid(const XdmfFrame& f) {
    os << "      <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"0\" NodesPerElement=\"1\"/>\n";
    os << "      <Geometry GeometryType=\"" << geometry << "\">";
    item(os, file, body_points(f.step), nb, d);
    os << "</Geometry>\n";
  }

  /// moreau-output/2 scenes with several modelizations: a grid per modelization, its nodes
  /// as points or its elements as cells, with every frame field of its sets.
  void model_sets(const std::vector<XdmfFrame>& frames) {
    for (const auto& set : layout.sets) {
      os << "  <Grid Name=\"" << set.name << "\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
      for (const auto& f : frames) {
        const std::string fp = frame_path(f.step);
        grid_start(os, set.name.c_str(), f);
        if (set.elements.empty()) {
          os << "      <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" << set.rows << "\" NodesPerElement=\"1\"/>\n";
        } else {
          os << "      <Topology TopologyType=\"Mixed\" NumberOfElements=\"" << set.cells << "\">";
          item(os, file, "/" + set.elements + "/cells", set.connectivity, 0, i32);
          os << "</Topology>\n";
        }
        os << "      <Geometry GeometryType=\"" << geometry << "\">";
        item(os, file, fp + "/" + set.nodes + "/position", set.rows, d);
        os << "</Geometry>\n";
        auto attributes = [&](const std::string& group, const std::vector<std::pair<std::string, int>>& fields,
                              std::size_t rows, const char* center) {
          for (const auto& [name, c] : fields) {
            const char* kind = c == 1 ? "Scalar" : c == d ? "Vector" : c == 4 ? "Matrix" : nullptr;
            if (!kind || name == node_fields::position) continue;
            attribute(os, name.c_str(), kind, file, fp + "/" + group + "/" + name, rows, c == 1 ? 0 : c, f64, center);
          }
        };
        attributes(set.nodes, set.node_fields, set.rows, "Node");
        if (!set.elements.empty()) attributes(set.elements, set.element_fields, set.cells, "Cell");
        os << "   </Grid>\n";
      }
      os << "  </Grid>\n";
    }
  }

  void bodies(const std::vector<XdmfFrame>& frames) {
    const char* vec = "Vector";
    os << "  <Grid Name=\"bodies\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
    for (const auto& f : frames) {
      const std::string fp = frame_path(f.step);
      grid_start(os, "bodies", f);
      os << "      <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" << nb << "\" NodesPerElement=\"1\"/>\n";
      os << "      <Geometry GeometryType=\"" << geometry << "\">";
      item(os, file, fp + "/position", nb, d);
      os << "</Geometry>\n";
      attribute(os, "velocity", vec, file, fp + "/velocity", nb, d);
      if (d == 2) {
        attribute(os, "angle", "Scalar", file, fp + "/angle", nb, 0);
        attribute(os, "angular_velocity", "Scalar", file, fp + "/angular_velocity", nb, 0);
      } else {
        attribute(os, "angular_velocity", vec, file, fp + "/angular_velocity", nb, 3);
        attribute(os, "orientation", "Matrix", file, fp + "/orientation", nb, 4);
      }
      attribute(os, "mass", "Scalar", file, "/bodies/mass", nb, 0);
      attribute(os, "fixed", "Scalar", file, "/bodies/fixed", nb, 0, i8);
      os << "   </Grid>\n";
    }
    os << "  </Grid>\n";
  }

  /// Cells (connectivity, body, contactor) from the header; vertices from each frame.
  void shapes(const std::vector<XdmfFrame>& frames, const XdmfDisplay& m) {
    os << "  <Grid Name=\"shapes\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
    for (const auto& f : frames) {
      if (!f.display) continue;  // written without display (continued from a "points" run)
      grid_start(os, "shapes", f);
      os << "      <Topology TopologyType=\"Mixed\" NumberOfElements=\"" << m.cells << "\">";
      item(os, file, "/display/cells", m.connectivity, 0, i32);
      os << "</Topology>\n      <Geometry GeometryType=\"" << geometry << "\">";
      item(os, file, frame_path(f.step) + "/display/points", m.vertices, d, f32);
      os << "</Geometry>\n";
      attribute(os, "body", "Scalar", file, "/display/cell_body", m.cells, 0, i32, "Cell");
      attribute(os, "contactor", "Scalar", file, "/display/cell_contactor", m.cells, 0, i32, "Cell");
      os << "   </Grid>\n";
    }
    os << "  </Grid>\n";
  }

  /// The contact laws' variables of a frame's contacts (scalars and d-vectors; an int8
  /// field with several components is written as int32, field_io.cpp).
  void law_fields(const std::string& cp, std::size_t nc, const char* center) {
    for (const auto& f : layout.contact_fields) {
      const char* kind = f.components == 1 ? "Scalar" : f.components == d ? "Vector" : nullptr;
      if (!kind) continue;
      const Type type = f.file == FileType::real ? f64 : f.file == FileType::int32 || f.components > 1 ? i32 : i8;
      attribute(os, f.name.c_str(), kind, file, cp + "/" + f.name, nc, f.components == 1 ? 0 : f.components, type, center);
    }
  }

  void contacts(const std::vector<XdmfFrame>& frames) {
    os << "  <Grid Name=\"contacts\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
    for (const auto& f : frames) {
      const std::string cp = frame_path(f.step) + "/contacts";
      grid_start(os, "contacts", f);
      if (f.contacts == 0) {
        empty_grid(f);
        os << "   </Grid>\n";
        continue;
      }
      const std::size_t nc = f.contacts;
      os << "      <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" << nc << "\" NodesPerElement=\"1\"/>\n";
      os << "      <Geometry GeometryType=\"" << geometry << "\">";
      item(os, file, cp + "/point", nc, d);
      os << "</Geometry>\n";
      attribute(os, "normal", "Vector", file, cp + "/normal", nc, d);
      attribute(os, "force", "Vector", file, cp + "/force", nc, d);
      if (f.normal_force) attribute(os, "normal_force", "Scalar", file, cp + "/normal_force", nc, 0);
      attribute(os, "gap", "Scalar", file, cp + "/gap", nc, 0);
      attribute(os, "status", "Scalar", file, cp + "/status", nc, 0, i8);
      law_fields(cp, nc, "Node");
      os << "   </Grid>\n";
    }
    os << "  </Grid>\n";
  }

  /// A polyline of 3 points per contact, centre – contact point – centre, from the
  /// frame's contacts/network (points in order: the connectivity is implicit, and no two
  /// lines share a point, so tubes can be sized per line). Frames written before it: a
  /// line between the two bodies' positions (connectivity contacts/bodies).
  void force_network(const std::vector<XdmfFrame>& frames) {
    os << "  <Grid Name=\"force_network\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
    for (const auto& f : frames) {
      const std::string fp = frame_path(f.step), cp = fp + "/contacts";
      grid_start(os, "force_network", f);
      if (f.contacts == 0) {
        empty_grid(f);
        os << "   </Grid>\n";
        continue;
      }
      const std::size_t nc = f.contacts;
      if (f.network) {
        os << "      <Topology TopologyType=\"Polyline\" NumberOfElements=\"" << nc << "\" NodesPerElement=\"3\"/>\n";
        os << "      <Geometry GeometryType=\"" << geometry << "\">";
        item(os, file, cp + "/network", 3 * nc, d, f32);
      } else {
        os << "      <Topology TopologyType=\"Polyline\" NumberOfElements=\"" << nc << "\" NodesPerElement=\"2\">";
        item(os, file, cp + "/bodies", nc, 2, i32);
        os << "</Topology>\n      <Geometry GeometryType=\"" << geometry << "\">";
        item(os, file, body_points(f.step), nb, d);
      }
      os << "</Geometry>\n";
      if (f.normal_force) attribute(os, "normal_force", "Scalar", file, cp + "/normal_force", nc, 0, f64, "Cell");
      attribute(os, "force", "Vector", file, cp + "/force", nc, d, f64, "Cell");
      attribute(os, "status", "Scalar", file, cp + "/status", nc, 0, i8, "Cell");
      law_fields(cp, nc, "Cell");
      os << "   </Grid>\n";
    }
    os << "  </Grid>\n";
  }
};

}  // namespace

void write_xdmf_file(const std::string& h5_path, int d, const std::vector<XdmfFrame>& frames, std::size_t nb,
                     const XdmfDisplay& display, const XdmfLayout& layout) {
  std::ostringstream os;
  os.precision(17);
  Writer w{os, fs::path(h5_path).filename().string(), d, d == 2 ? "XY" : "XYZ", nb, layout};
  os << "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"3.0\">\n <Domain>\n";
  if (layout.legacy) w.bodies(frames);
  else w.model_sets(frames);
  bool any_display = false, any_contacts = false;
  for (const auto& f : frames) {
    any_display |= f.display;
    any_contacts |= f.contacts > 0;
  }
  if (any_display && display.cells > 0) w.shapes(frames, display);
  if (any_contacts) {
    w.contacts(frames);
    w.force_network(frames);
  }
  os << " </Domain>\n</Xdmf>\n";

  const std::string target = xdmf_path(h5_path);
  const std::string tmp = target + ".tmp";
  std::error_code ec;
  {
    std::ofstream out(tmp, std::ios::trunc);
    out << os.str();
    out.close();
    if (!out) {  // the viewer description is a convenience: never fail the run for it
      fs::remove(tmp, ec);
      return;
    }
  }
  fs::rename(tmp, target, ec);
  if (ec) fs::remove(tmp, ec);
}

}  // namespace moreau::io
