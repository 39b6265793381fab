#include "mesh.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <sstream>
#include <tuple>

#include "element_geometry.hpp"

namespace moreau::fem {

void Cells::add(ElementType t, std::span<const int> cell_nodes) {
  type.push_back(t);
  nodes.insert(nodes.end(), cell_nodes.begin(), cell_nodes.end());
  offset.push_back(static_cast<int>(nodes.size()));
}

void Cells::reserve(int cells, int total_nodes) {
  type.reserve(cells);
  offset.reserve(cells + 1);
  nodes.reserve(total_nodes);
}

std::int64_t Mesh::element_label(int e) const {
  return element_number.empty() ? e + 1 : element_number[e];
}

std::int64_t Mesh::node_label(int n) const { return node_number.empty() ? n + 1 : node_number[n]; }

std::string Mesh::describe_element(int e) const {
  std::ostringstream s;
  s << "element " << element_label(e);
  const long line = element_line.empty() ? 0 : element_line[e];
  if (from_file) {
    s << " (" << source;
    if (line > 0) s << ":" << line;
    s << ")";
  } else if (!source.empty()) {
    s << " of the " << source << " mesh";
  }
  return s.str();
}

namespace {

template <class Map>
const typename Map::mapped_type& find_set(const Mesh& mesh, const Map& sets, const std::string& name,
                                          const char* kind) {
  const auto it = sets.find(name);
  if (it != sets.end()) return it->second;
  std::string valid;
  for (const auto& [key, value] : sets) valid += (valid.empty() ? "" : ", ") + ("'" + key + "'");
  throw MeshError("the " + (mesh.source.empty() ? std::string("mesh") : mesh.source) + " mesh has no " +
                      kind + " set '" + name + "'; valid: " + (valid.empty() ? "(none)" : valid),
                  mesh.from_file ? mesh.source : "");
}

/// A face identified by its sorted corner nodes (unused slots −1).
using FaceKey = std::array<int, 4>;

FaceKey face_key(std::span<const int> nodes, int corners) {
  FaceKey k{-1, -1, -1, -1};
  for (int i = 0; i < corners && i < 4; ++i) {  // insertion sort of at most 4 numbers
    int j = i;
    for (; j > 0 && k[j - 1] > nodes[i]; --j) k[j] = k[j - 1];
    k[j] = nodes[i];
  }
  return k;
}

struct FaceEntry {
  FaceKey key;
  int element, face;
  bool operator<(const FaceEntry& o) const {
    return std::tie(key, element, face) < std::tie(o.key, o.element, o.face);
  }
};

/// Every face of every element, sorted by key.
std::vector<FaceEntry> all_faces(const Mesh& mesh) {
  std::vector<FaceEntry> faces;
  std::array<int, 8> local{};
  for (int e = 0; e < mesh.element_count(); ++e) {
    const ElementInfo& info = element_info(mesh.elements.type[e]);
    const auto cell = mesh.elements[e];
    for (int f = 0; f < static_cast<int>(info.faces.size()); ++f) {
      const FaceInfo& fi = info.faces[f];
      const int corners = element_info(fi.type).corners;
      for (int a = 0; a < corners; ++a) local[a] = cell[fi.nodes[a]];
      faces.push_back({face_key(local, corners), e, f});
    }
  }
  std::sort(faces.begin(), faces.end());
  return faces;
}

void add_face(const Mesh& mesh, Facets& out, int e, int f) {
  const FaceInfo& fi = element_info(mesh.elements.type[e]).faces[f];
  const auto cell = mesh.elements[e];
  std::array<int, 8> nodes{};
  const int n = element_info(fi.type).nodes;
  for (int a = 0; a < n; ++a) nodes[a] = cell[fi.nodes[a]];
  out.cells.add(fi.type, std::span<const int>(nodes.data(), n));
  out.element.push_back(e);
  out.face.push_back(f);
}

}  // namespace

const std::vector<int>& Mesh::node_set(const std::string& name) const {
  return find_set(*this, node_sets, name, "node");
}
const std::vector<int>& Mesh::element_set(const std::string& name) const {
  return find_set(*this, element_sets, name, "element");
}
const Facets& Mesh::boundary_set(const std::string& name) const {
  return find_set(*this, boundary_sets, name, "boundary");
}

Facets boundary_facets(const Mesh& mesh) {
  const std::vector<FaceEntry> faces = all_faces(mesh);
  std::vector<std::pair<int, int>> once;  // (element, face)
  for (std::size_t i = 0; i < faces.size();) {
    std::size_t j = i + 1;
    while (j < faces.size() && faces[j].key == faces[i].key) ++j;
    if (j == i + 1) once.emplace_back(faces[i].element, faces[i].face);
    i = j;
  }
  std::sort(once.begin(), once.end());
  Facets out;
  for (const auto& [e, f] : once) add_face(mesh, out, e, f);
  return out;
}

std::vector<int> facet_nodes(const Facets& facets) {
  std::vector<int> nodes = facets.cells.nodes;
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}

Eigen::Vector3d facet_normal(const Mesh& mesh, const Facets& facets, int i, double* measure) {
  const auto nodes = facets.cells[i];
  Eigen::Vector3d p[4];
  const int corners = element_info(facets.cells.type[i]).corners;
  for (int a = 0; a < corners; ++a) {
    p[a].setZero();
    p[a].head(mesh.dim) = mesh.x.col(nodes[a]);
  }
  Eigen::Vector3d n;
  if (mesh.dim == 2) {
    const Eigen::Vector3d t = p[1] - p[0];
    n = Eigen::Vector3d(t.y(), -t.x(), 0);  // the edge turned by −90°
    if (measure) *measure = n.norm();
  } else if (corners == 3) {
    n = (p[1] - p[0]).cross(p[2] - p[0]);
    if (measure) *measure = 0.5 * n.norm();
  } else {  // quadrangle: the cross product of the diagonals is twice its vector area
    n = (p[2] - p[0]).cross(p[3] - p[1]);
    if (measure) *measure = 0.5 * n.norm();
  }
  return n.normalized();
}

Facets match_facets(const Mesh& mesh, const Cells& faces, const std::function<MeshError(int)>& fault) {
  const std::vector<FaceEntry> all = all_faces(mesh);
  Facets out;
  for (int f = 0; f < faces.size(); ++f) {
    const int corners = element_info(faces.type[f]).corners;
    const FaceKey key = face_key(faces[f], corners);
    const auto it = std::lower_bound(all.begin(), all.end(), FaceEntry{key, -1, -1});
    if (it == all.end() || it->key != key) throw fault(f);
    // A face between two elements (an interface) takes the first element's orientation.
    add_face(mesh, out, it->element, it->face);
  }
  return out;
}

double element_measure(const Mesh& mesh, int e) {
  detail::ElementGeometry g;
  g.bind(mesh, e);
  double m = 0;
  for (const QuadraturePoint& q : element_info(g.type).rule) m += g.evaluate(q.xi.data()) * q.weight;
  return m;
}

}  // namespace moreau::fem
