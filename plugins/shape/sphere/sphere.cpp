// `sphere` (3D): a sphere of `radius` centred on the body origin.
#include <array>
#include <cmath>
#include <map>
#include <moreau/shape.hpp>
#include <numbers>
#include <utility>

namespace {
using namespace moreau;

/// An icosahedron subdivided once, its vertices pushed onto the sphere: 42 vertices and 80
/// triangles, counter-clockwise from outside, evenly spread (a UV sphere crowds the poles).
DisplayMesh icosphere(double r) {
  const double t = (1 + std::sqrt(5.0)) / 2;
  std::vector<std::array<double, 3>> v = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                                          {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  const std::vector<std::array<int, 3>> faces = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                                 {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                                 {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                                 {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  std::map<std::pair<int, int>, int> middle;  // an edge's midpoint, shared by its two faces
  auto mid = [&](int a, int b) {
    const auto key = std::minmax(a, b);
    const auto [it, added] = middle.try_emplace(key, static_cast<int>(v.size()));
    if (added) v.push_back({(v[a][0] + v[b][0]) / 2, (v[a][1] + v[b][1]) / 2, (v[a][2] + v[b][2]) / 2});
    return it->second;
  };
  DisplayMesh m;
  for (const auto& f : faces) {
    const int ab = mid(f[0], f[1]), bc = mid(f[1], f[2]), ca = mid(f[2], f[0]);
    for (const std::array<int, 3> tri : {std::array{f[0], ab, ca}, std::array{f[1], bc, ab},
                                         std::array{f[2], ca, bc}, std::array{ab, bc, ca}}) {
      m.indices.insert(m.indices.end(), tri.begin(), tri.end());
      m.sizes.push_back(3);
    }
  }
  for (const auto& p : v) {
    const double s = r / std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    m.points.insert(m.points.end(), {s * p[0], s * p[1], s * p[2]});
  }
  return m;
}

class Sphere : public Shape {
 public:
  static Schema schema() {
    Schema s;
    s.number("radius", "sphere radius").units("m").gt(0);
    s.dimensions({3});
    return s;
  }
  static constexpr const char* doc = "sphere (3D)";
  Sphere(const Params& p, const BuildContext&) : g_{p.number("radius")} {}
  const char* shape_name() const override { return "sphere"; }
  const std::vector<double>& geometry() const override { return g_; }
  MassProperties mass_properties() const override {
    const double r = g_[0], r5 = r * r * r * r * r;
    MassProperties m;
    m.volume = 4.0 / 3.0 * std::numbers::pi * r * r * r;
    m.inertia[0] = m.inertia[4] = m.inertia[8] = 8.0 / 15.0 * std::numbers::pi * r5;  // (2/5) V r²
    return m;
  }
  void bounds(int, const Pose& p, double lo[3], double hi[3]) const override {
    for (int k = 0; k < 3; ++k) {
      lo[k] = p.position[k] - g_[0];
      hi[k] = p.position[k] + g_[0];
    }
  }
  DisplayMesh display_mesh(double) const override { return icosphere(g_[0]); }

 private:
  std::vector<double> g_;
};
MOREAU_REGISTER(Sphere, "sphere")
}  // namespace
MOREAU_PLUGIN_LIBRARY("moreau_shape_sphere")
