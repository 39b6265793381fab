#include "mesh_generate.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <unordered_map>

#include "element_geometry.hpp"

namespace moreau::fem {
namespace {

constexpr double max_elements = 1e7;

void require_length(const char* mesh, const char* what, double value) {
  if (!std::isfinite(value) || value <= 0) {
    std::ostringstream s;
    s << mesh << " mesh: " << what << " must be a finite value > 0, got " << value;
    throw MeshError(s.str());
  }
}

int divisions(double length, double size) {
  return std::max(1, static_cast<int>(std::ceil(length / size - 1e-9)));
}

void require_count(const char* mesh, double elements) {
  if (elements > max_elements) {
    std::ostringstream s;
    s << mesh << " mesh: the size would give " << elements << " elements (at most " << max_elements
      << "); choose a larger size";
    throw MeshError(s.str());
  }
}

void require_type(const char* mesh, ElementType type, ElementType a, ElementType b) {
  if (type != a && type != b)
    throw MeshError(std::string(mesh) + " mesh: element type " + std::string(element_info(type).name) +
                    " is not available; valid: " + std::string(element_info(a).name) + ", " +
                    std::string(element_info(b).name));
}

/// Makes every element positively oriented (generators build them by a pattern whose
/// orientation depends on the block).
void orient_positive(Mesh& mesh) {
  for (int e = 0; e < mesh.element_count(); ++e) {
    if (element_measure(mesh, e) < 0) reverse_orientation(mesh.elements.type[e], mesh.elements.at(e));
  }
}

/// Splits a quadrangle (counter-clockwise) into two triangles along its shorter diagonal
/// (the 0–2 diagonal on a tie, so rectangles are all cut the same way).
void add_quad(Mesh& mesh, ElementType type, std::array<int, 4> q) {
  if (type == ElementType::Q4) {
    mesh.elements.add(type, q);
    return;
  }
  const double d02 = (mesh.x.col(q[2]) - mesh.x.col(q[0])).squaredNorm();
  const double d13 = (mesh.x.col(q[3]) - mesh.x.col(q[1])).squaredNorm();
  if (d02 <= d13 * (1 + 1e-12)) {
    mesh.elements.add(type, std::array{q[0], q[1], q[2]});
    mesh.elements.add(type, std::array{q[0], q[2], q[3]});
  } else {
    mesh.elements.add(type, std::array{q[0], q[1], q[3]});
    mesh.elements.add(type, std::array{q[1], q[2], q[3]});
  }
}

/// Names the element set "all", the boundary set "boundary" and, for an axis-aligned
/// block, the sides xmin … zmax by their outward normals; each boundary set also becomes a
/// node set.
void name_sets(Mesh& mesh, bool sides) {
  std::vector<int> all(mesh.element_count());
  for (int e = 0; e < mesh.element_count(); ++e) all[e] = e;
  mesh.element_sets["all"] = std::move(all);
  Facets boundary = boundary_facets(mesh);
  if (sides) {
    static const char* names[3][2] = {{"xmin", "xmax"}, {"ymin", "ymax"}, {"zmin", "zmax"}};
    for (int f = 0; f < boundary.size(); ++f) {
      const Eigen::Vector3d n = facet_normal(mesh, boundary, f);
      for (int k = 0; k < mesh.dim; ++k) {
        if (std::abs(std::abs(n[k]) - 1) > 1e-9) continue;
        Facets& set = mesh.boundary_sets[names[k][n[k] > 0]];
        set.cells.add(boundary.cells.type[f], boundary.cells[f]);
        set.element.push_back(boundary.element[f]);
        set.face.push_back(boundary.face[f]);
      }
    }
  }
  mesh.boundary_sets["boundary"] = std::move(boundary);
  for (const auto& [name, facets] : mesh.boundary_sets) mesh.node_sets[name] = facet_nodes(facets);
}

/// Points merged when closer than a tolerance (a hash grid of cells of that size).
class PointMerger {
 public:
  PointMerger(Mesh& mesh, double tolerance) : mesh_(mesh), tol_(tolerance) {}
  int add(double x, double y) {
    const long ix = std::lround(std::floor(x / tol_)), iy = std::lround(std::floor(y / tol_));
    for (long dx = -1; dx <= 1; ++dx)
      for (long dy = -1; dy <= 1; ++dy) {
        const auto it = grid_.find(key(ix + dx, iy + dy));
        if (it == grid_.end()) continue;
        for (int n : it->second)
          if (std::hypot(points_[n][0] - x, points_[n][1] - y) <= tol_) return n;
      }
    const int n = static_cast<int>(points_.size());
    points_.push_back({x, y});
    grid_[key(ix, iy)].push_back(n);
    return n;
  }
  void finish() {
    mesh_.x.resize(2, static_cast<Eigen::Index>(points_.size()));
    for (std::size_t n = 0; n < points_.size(); ++n) mesh_.x.col(static_cast<Eigen::Index>(n)) << points_[n][0], points_[n][1];
  }

 private:
  static std::uint64_t key(long ix, long iy) {
    return (static_cast<std::uint64_t>(ix) * 0x9E3779B97F4A7C15ull) ^ static_cast<std::uint64_t>(iy);
  }
  Mesh& mesh_;
  double tol_;
  std::vector<std::array<double, 2>> points_;
  std::unordered_map<std::uint64_t, std::vector<int>> grid_;
};

}  // namespace

Mesh rectangle_mesh(std::array<double, 2> origin, std::array<double, 2> extent, double size, ElementType type) {
  require_type("rectangle", type, ElementType::T3, ElementType::Q4);
  require_length("rectangle", "width", extent[0]);
  require_length("rectangle", "height", extent[1]);
  require_length("rectangle", "size", size);
  if (!std::isfinite(origin[0]) || !std::isfinite(origin[1])) throw MeshError("rectangle mesh: origin must be finite");
  const int nx = divisions(extent[0], size), ny = divisions(extent[1], size);
  require_count("rectangle", double(nx) * ny * (type == ElementType::T3 ? 2 : 1));
  Mesh mesh;
  mesh.dim = 2;
  mesh.source = "rectangle";
  mesh.x.resize(2, (nx + 1) * (ny + 1));
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i)
      mesh.x.col(j * (nx + 1) + i) << origin[0] + extent[0] * i / nx, origin[1] + extent[1] * j / ny;
  const int per = type == ElementType::T3 ? 3 : 4, cells = type == ElementType::T3 ? 2 : 1;
  mesh.elements.reserve(nx * ny * cells, nx * ny * cells * per);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int a = j * (nx + 1) + i;
      add_quad(mesh, type, {a, a + 1, a + nx + 2, a + nx + 1});
    }
  name_sets(mesh, true);
  return mesh;
}

Mesh disk_mesh(std::array<double, 2> centre, double radius, double size, ElementType type) {
  require_type("disk", type, ElementType::T3, ElementType::Q4);
  require_length("disk", "radius", radius);
  require_length("disk", "size", size);
  if (!std::isfinite(centre[0]) || !std::isfinite(centre[1])) throw MeshError("disk mesh: centre must be finite");
  // Square core [−a, a]² with n × n cells (n even, so the centre is a node); four blocks
  // from the core's sides out to quarter arcs, n cells along and m across.
  const double pi = std::numbers::pi, a = 0.5 * radius;
  int n = std::max(2, divisions(0.5 * pi * radius, size));
  n += n % 2;
  const int m = std::max(1, divisions(0.4 * radius, size));
  require_count("disk", (double(n) * n + 4.0 * n * m) * (type == ElementType::T3 ? 2 : 1));
  Mesh mesh;
  mesh.dim = 2;
  mesh.source = "disk";
  PointMerger points(mesh, 1e-9 * radius);
  std::vector<int> grid((n + 1) * (n + 1));
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      grid[j * (n + 1) + i] = points.add(centre[0] - a + 2 * a * i / n, centre[1] - a + 2 * a * j / n);
  std::vector<int> quads;  // four node numbers per cell
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int p = j * (n + 1) + i;
      quads.insert(quads.end(), {grid[p], grid[p + 1], grid[p + n + 2], grid[p + n + 1]});
    }
  std::vector<int> block((n + 1) * (m + 1));
  for (int k = 0; k < 4; ++k) {
    const double c = std::cos(k * pi / 2), s = std::sin(k * pi / 2);
    for (int j = 0; j <= m; ++j)
      for (int i = 0; i <= n; ++i) {
        // The right-hand block (inner side x = a, arc from −45° to 45°), turned by k·90°.
        const double u = double(i) / n, t = double(j) / m, phi = -pi / 4 + pi / 2 * u;
        const double px = (1 - t) * a + t * radius * std::cos(phi);
        const double py = (1 - t) * (-a + 2 * a * u) + t * radius * std::sin(phi);
        block[j * (n + 1) + i] = points.add(centre[0] + c * px - s * py, centre[1] + s * px + c * py);
      }
    for (int j = 0; j < m; ++j)
      for (int i = 0; i < n; ++i) {
        const int p = j * (n + 1) + i;
        quads.insert(quads.end(), {block[p], block[p + 1], block[p + n + 2], block[p + n + 1]});
      }
  }
  points.finish();
  const int cells = static_cast<int>(quads.size() / 4);
  mesh.elements.reserve(cells * 2, cells * 6);
  for (int q = 0; q < cells; ++q) {
    std::array<int, 4> quad{quads[4 * q], quads[4 * q + 1], quads[4 * q + 2], quads[4 * q + 3]};
    // Orient the quadrangle before a split so both triangles come out positive.
    Eigen::Vector2d d1 = mesh.x.col(quad[2]) - mesh.x.col(quad[0]), d2 = mesh.x.col(quad[3]) - mesh.x.col(quad[1]);
    if (d1.x() * d2.y() - d1.y() * d2.x() < 0) std::swap(quad[1], quad[3]);
    add_quad(mesh, type, quad);
  }
  name_sets(mesh, false);
  mesh.node_sets["centre"] = {grid[(n / 2) * (n + 1) + n / 2]};
  return mesh;
}

Mesh box_mesh(std::array<double, 3> origin, std::array<double, 3> extent, double size, ElementType type) {
  require_type("box", type, ElementType::T4, ElementType::H8);
  static const char* sides[3] = {"x extent", "y extent", "z extent"};
  for (int k = 0; k < 3; ++k) {
    require_length("box", sides[k], extent[k]);
    if (!std::isfinite(origin[k])) throw MeshError("box mesh: origin must be finite");
  }
  require_length("box", "size", size);
  const int nx = divisions(extent[0], size), ny = divisions(extent[1], size), nz = divisions(extent[2], size);
  require_count("box", double(nx) * ny * nz * (type == ElementType::T4 ? 6 : 1));
  Mesh mesh;
  mesh.dim = 3;
  mesh.source = "box";
  const auto id = [&](int i, int j, int k) { return (k * (ny + 1) + j) * (nx + 1) + i; };
  mesh.x.resize(3, (nx + 1) * (ny + 1) * (nz + 1));
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i)
        mesh.x.col(id(i, j, k)) << origin[0] + extent[0] * i / nx, origin[1] + extent[1] * j / ny,
            origin[2] + extent[2] * k / nz;
  const int cells = type == ElementType::T4 ? 6 : 1;
  mesh.elements.reserve(nx * ny * nz * cells, nx * ny * nz * 8);
  // The six tetrahedra of a cell follow the paths from corner (0,0,0) to (1,1,1) along the
  // axes in each order (Kuhn's subdivision).
  static const int orders[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        if (type == ElementType::H8) {
          mesh.elements.add(type, std::array{id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k),
                                             id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1),
                                             id(i, j + 1, k + 1)});
          continue;
        }
        for (const auto& order : orders) {
          std::array<int, 3> c{i, j, k};
          std::array<int, 4> tet{};
          tet[0] = id(c[0], c[1], c[2]);
          for (int s = 0; s < 3; ++s) {
            ++c[order[s]];
            tet[s + 1] = id(c[0], c[1], c[2]);
          }
          mesh.elements.add(type, tet);
        }
      }
  orient_positive(mesh);
  name_sets(mesh, true);
  return mesh;
}

}  // namespace moreau::fem
