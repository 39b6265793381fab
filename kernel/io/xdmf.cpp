#include "xdmf.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace moreau::io {

namespace fs = std::filesystem;

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

void item(std::ostream& os, const std::string& file, const std::string& path, std::size_t rows, int cols,
          const char* type = "Float", int precision = 8) {
  os << "<DataItem Dimensions=\"" << rows;
  if (cols > 0) os << " " << cols;
  os << "\" NumberType=\"" << type << "\" Precision=\"" << precision << "\" Format=\"HDF\">" << file << ":" << path
     << "</DataItem>";
}

void attribute(std::ostream& os, const char* name, const char* kind, const std::string& file, const std::string& path,
               std::size_t rows, int cols, const char* type = "Float", int precision = 8) {
  os << "      <Attribute Name=\"" << name << "\" AttributeType=\"" << kind << "\" Center=\"Node\">";
  item(os, file, path, rows, cols, type, precision);
  os << "</Attribute>\n";
}

}  // namespace

void write_xdmf_file(const std::string& h5_path, int d, const std::vector<XdmfFrame>& frames, std::size_t nb) {
  const std::string file = fs::path(h5_path).filename().string();  // relative: the pair can be moved together
  std::ostringstream os;
  os.precision(17);
  const char* geometry = d == 2 ? "XY" : "XYZ";
  const char* vec = "Vector";
  os << "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"3.0\">\n <Domain>\n";
  os << "  <Grid Name=\"bodies\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  for (const auto& f : frames) {
    const std::string fp = frame_path(f.step);
    os << "   <Grid Name=\"bodies " << f.step << "\" GridType=\"Uniform\">\n      <Time Value=\"" << f.time << "\"/>\n";
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
    attribute(os, "fixed", "Scalar", file, "/bodies/fixed", nb, 0, "Char", 1);
    os << "   </Grid>\n";
  }
  os << "  </Grid>\n";
  bool any_contacts = false;
  for (const auto& f : frames) any_contacts |= f.contacts > 0;
  if (any_contacts) {
    os << "  <Grid Name=\"contacts\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
    for (const auto& f : frames) {
      const std::string cp = frame_path(f.step) + "/contacts";
      os << "   <Grid Name=\"contacts " << f.step << "\" GridType=\"Uniform\">\n      <Time Value=\"" << f.time << "\"/>\n";
      os << "      <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" << f.contacts << "\" NodesPerElement=\"1\"/>\n";
      if (f.contacts > 0) {
        os << "      <Geometry GeometryType=\"" << geometry << "\">";
        item(os, file, cp + "/point", f.contacts, d);
        os << "</Geometry>\n";
        attribute(os, "normal", vec, file, cp + "/normal", f.contacts, d);
        attribute(os, "force", vec, file, cp + "/force", f.contacts, d);
        attribute(os, "gap", "Scalar", file, cp + "/gap", f.contacts, 0);
        attribute(os, "status", "Scalar", file, cp + "/status", f.contacts, 0, "Char", 1);
      } else {
        os << "      <Geometry GeometryType=\"" << geometry << "\"><DataItem Dimensions=\"0 " << d
           << "\" Format=\"XML\"></DataItem></Geometry>\n";
      }
      os << "   </Grid>\n";
    }
    os << "  </Grid>\n";
  }
  os << " </Domain>\n</Xdmf>\n";

  const std::string target = xdmf_path(h5_path);
  const std::string tmp = target + ".tmp";
  {
    std::ofstream out(tmp, std::ios::trunc);
    out << os.str();
    if (!out) return;  // the viewer description is a convenience: never fail the run for it
  }
  std::error_code ec;
  fs::rename(tmp, target, ec);
}

}  // namespace moreau::io
