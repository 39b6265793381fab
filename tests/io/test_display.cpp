// Bodies drawn as their shapes (output `display`, docs/output.md): the header's /display
// meshes and each frame's world vertices, checked against the analytic shapes.
#include <gtest/gtest.h>
#include <hdf5.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>

#include "cli_runner.hpp"
#include "display_scenes.hpp"

namespace fs = std::filesystem;
using namespace moreau_test;

namespace {

struct SceneRun {
  fs::path dir;
  hid_t file = -1;
  ~SceneRun() {
    if (file >= 0) H5Fclose(file);
  }
};

void run_scene(SceneRun& r, const std::string& name, const std::string& scene) {
  r.dir = scratch_dir(name);
  const fs::path path = write_file(r.dir, "scene.json", scene);
  const Result res = run_moreau({"run", path.string(), "--quiet"}, r.dir);
  ASSERT_EQ(res.code, 0) << res.err;
  r.file = H5Fopen((r.dir / "out.h5").string().c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(r.file, 0);
}

/// The cells of an XDMF Mixed connectivity, each as its vertex list.
std::vector<std::vector<int>> decode_cells(const std::vector<int>& c) {
  std::vector<std::vector<int>> cells;
  for (std::size_t at = 0; at < c.size();) {
    const int type = c[at++];
    const int n = type == 1 || type == 3 ? c[at++] : type == 4 ? 3 : type == 5 ? 4 : -1;
    if (n < 0) throw std::runtime_error("unexpected cell type " + std::to_string(type));
    cells.emplace_back(c.begin() + at, c.begin() + at + n);
    at += n;
  }
  return cells;
}

/// The display mesh as written: cells, and for each contactor its vertices in order.
struct Mesh {
  std::vector<std::vector<int>> cells;
  std::vector<int> cell_contactor;
  std::vector<std::vector<int>> contactor_vertices;
};

Mesh read_mesh(hid_t f) {
  Mesh m;
  m.cells = decode_cells(read_as<int>(f, "/display/cells", H5T_NATIVE_INT));
  m.cell_contactor = read_as<int>(f, "/display/cell_contactor", H5T_NATIVE_INT);
  for (std::size_t c = 0; c < m.cells.size(); ++c) {
    const std::size_t k = static_cast<std::size_t>(m.cell_contactor[c]);
    if (m.contactor_vertices.size() <= k) m.contactor_vertices.resize(k + 1);
    auto& vs = m.contactor_vertices[k];
    for (int v : m.cells[c])
      if (std::find(vs.begin(), vs.end(), v) == vs.end()) vs.push_back(v);
  }
  for (auto& vs : m.contactor_vertices) std::sort(vs.begin(), vs.end());
  return m;
}

/// float32 keeps ~6e-8 relative: 1e-6 of the coordinate's size (at least 1 m) is margin.
double tolerance(double x) { return 1e-6 * std::max(1.0, std::fabs(x)); }

std::array<double, 9> quaternion_matrix(const double* q) {
  const double w = q[0], x = q[1], y = q[2], z = q[3];
  return {1 - 2 * (y * y + z * z), 2 * (x * y - w * z),     2 * (x * z + w * y),
          2 * (x * y + w * z),     1 - 2 * (x * x + z * z), 2 * (y * z - w * x),
          2 * (x * z - w * y),     2 * (y * z + w * x),     1 - 2 * (x * x + y * y)};
}

std::string frame(const char* step, const char* dataset) { return std::string("/frames/") + step + "/" + dataset; }

}  // namespace

TEST(Display, Datasets2D) {
  SceneRun r;
  ASSERT_NO_FATAL_FAILURE(run_scene(r, "display2d", display_scene_2d()));
  // Segment (2 × 13), disk (24), square (4), two disks (2 × 24): one polygon each.
  const hsize_t nv = 26 + 24 + 4 + 48, ncells = 5, nconn = (2 + 26) + (2 + 24) + (1 + 4) + 2 * (2 + 24);
  DatasetInfo i;
  ASSERT_TRUE(dataset_info(r.file, "/display/points", i));
  EXPECT_EQ(i.dims, (std::vector<hsize_t>{nv, 2}));
  EXPECT_EQ(i.type_class, H5T_FLOAT);
  EXPECT_EQ(i.type_size, 8u);
  ASSERT_TRUE(dataset_info(r.file, "/display/point_body", i));
  EXPECT_EQ(i.dims, (std::vector<hsize_t>{nv}));
  ASSERT_TRUE(dataset_info(r.file, "/display/cells", i));
  EXPECT_EQ(i.dims, (std::vector<hsize_t>{nconn}));
  EXPECT_EQ(i.type_class, H5T_INTEGER);
  EXPECT_EQ(i.type_size, 4u);
  for (const char* p : {"/display/cell_body", "/display/cell_contactor"}) {
    ASSERT_TRUE(dataset_info(r.file, p, i)) << p;
    EXPECT_EQ(i.dims, (std::vector<hsize_t>{ncells})) << p;
  }
  for (const char* step : {"00000000", "00000005", "00000010"}) {
    ASSERT_TRUE(dataset_info(r.file, frame(step, "display/points"), i)) << step;
    EXPECT_EQ(i.dims, (std::vector<hsize_t>{nv, 2}));
    EXPECT_EQ(i.type_class, H5T_FLOAT);
    EXPECT_EQ(i.type_size, 4u) << "world vertices are float32";
  }
  EXPECT_EQ(read_as<int>(r.file, "/display/cell_body", H5T_NATIVE_INT), (std::vector<int>{0, 1, 2, 3, 3}));
  EXPECT_EQ(read_as<int>(r.file, "/display/cell_contactor", H5T_NATIVE_INT), (std::vector<int>{0, 1, 2, 3, 4}));
}

TEST(Display, Datasets3D) {
  SceneRun r;
  ASSERT_NO_FATAL_FAILURE(run_scene(r, "display3d", display_scene_3d()));
  // Plane patch (4, a quad), box (8, 6 quads), icosphere (42, 80 triangles), tetrahedron (4, 4 triangles).
  const hsize_t nv = 4 + 8 + 42 + 4, ncells = 1 + 6 + 80 + 4, nconn = 5 + 6 * 5 + 80 * 4 + 4 * 4;
  DatasetInfo i;
  ASSERT_TRUE(dataset_info(r.file, "/display/points", i));
  EXPECT_EQ(i.dims, (std::vector<hsize_t>{nv, 3}));
  ASSERT_TRUE(dataset_info(r.file, "/display/cells", i));
  EXPECT_EQ(i.dims, (std::vector<hsize_t>{nconn}));
  ASSERT_TRUE(dataset_info(r.file, "/display/cell_contactor", i));
  EXPECT_EQ(i.dims, (std::vector<hsize_t>{ncells}));
  for (const char* step : {"00000000", "00000005", "00000010"}) {
    ASSERT_TRUE(dataset_info(r.file, frame(step, "display/points"), i)) << step;
    EXPECT_EQ(i.dims, (std::vector<hsize_t>{nv, 3}));
    EXPECT_EQ(i.type_size, 4u);
  }
  const Mesh m = read_mesh(r.file);
  ASSERT_EQ(m.contactor_vertices.size(), 4u);
  EXPECT_EQ(m.contactor_vertices[2].size(), 42u);
  EXPECT_EQ(std::count(m.cell_contactor.begin(), m.cell_contactor.end(), 2), 80);
}

// The wheel (disk r = 0.1 at (1, 0.15), angle 0.3) and the cluster `pair` (disks r = 0.05 at
// offsets ±0.05, body angle 0.2): vertex i is at x + R(θ) (o + r (cos 2πi/24, sin 2πi/24)).
TEST(Display, DiskVerticesOnTheCircle) {
  SceneRun r;
  ASSERT_NO_FATAL_FAILURE(run_scene(r, "display_disk", display_scene_2d()));
  const Mesh m = read_mesh(r.file);
  ASSERT_EQ(m.contactor_vertices.size(), 5u);
  struct Case {
    int contactor, body;
    double radius, offset;
  };
  for (const char* step : {"00000000", "00000010"}) {
    const auto world = read_as<double>(r.file, frame(step, "display/points"), H5T_NATIVE_DOUBLE);
    const auto x = read_as<double>(r.file, frame(step, "position"), H5T_NATIVE_DOUBLE);
    const auto angle = read_as<double>(r.file, frame(step, "angle"), H5T_NATIVE_DOUBLE);
    if (std::string(step) == "00000000") {  // the scene's pose, literally
      EXPECT_DOUBLE_EQ(x[2], 1);
      EXPECT_DOUBLE_EQ(x[3], 0.15);
      EXPECT_DOUBLE_EQ(angle[1], 0.3);
      EXPECT_DOUBLE_EQ(angle[3], 0.2);
    }
    for (const Case c : {Case{1, 1, 0.1, 0}, Case{3, 3, 0.05, -0.05}, Case{4, 3, 0.05, 0.05}}) {
      const auto& vs = m.contactor_vertices[c.contactor];
      ASSERT_EQ(vs.size(), 24u);
      const double th = angle[c.body], cs = std::cos(th), sn = std::sin(th);
      for (int i = 0; i < 24; ++i) {
        const double a = 2 * std::numbers::pi * i / 24;
        const double px = c.offset + c.radius * std::cos(a), py = c.radius * std::sin(a);
        const double ex = x[2 * c.body] + cs * px - sn * py, ey = x[2 * c.body + 1] + sn * px + cs * py;
        const int v = vs[i];
        EXPECT_NEAR(world[2 * v], ex, tolerance(ex)) << step << " contactor " << c.contactor << " vertex " << i;
        EXPECT_NEAR(world[2 * v + 1], ey, tolerance(ey)) << step << " contactor " << c.contactor << " vertex " << i;
      }
    }
  }
}

// The crate: box [0.4, 0.2, 0.1] at (1, 2, 0.05) turned 0.5 rad about z; its 8 display
// vertices are the corners x + R (±0.2, ±0.1, ±0.05), at the start and after moving.
TEST(Display, BoxVerticesAtTheCorners) {
  SceneRun r;
  ASSERT_NO_FATAL_FAILURE(run_scene(r, "display_box", display_scene_3d()));
  const Mesh m = read_mesh(r.file);
  const auto& vs = m.contactor_vertices[1];
  ASSERT_EQ(vs.size(), 8u);
  for (const char* step : {"00000000", "00000010"}) {
    const auto world = read_as<double>(r.file, frame(step, "display/points"), H5T_NATIVE_DOUBLE);
    const auto x = read_as<double>(r.file, frame(step, "position"), H5T_NATIVE_DOUBLE);
    const auto q = read_as<double>(r.file, frame(step, "orientation"), H5T_NATIVE_DOUBLE);
    if (std::string(step) == "00000000") {
      EXPECT_DOUBLE_EQ(x[3], 1);
      EXPECT_DOUBLE_EQ(x[4], 2);
      EXPECT_DOUBLE_EQ(x[5], 0.05);
      EXPECT_NEAR(q[4], std::cos(0.25), 1e-15);
      EXPECT_NEAR(q[7], std::sin(0.25), 1e-15);
    }
    const auto R = quaternion_matrix(&q[4]);
    std::vector<bool> seen(8, false);
    for (int v : vs) {
      int match = -1;
      for (int corner = 0; corner < 8; ++corner) {
        const double s[3] = {(corner & 1 ? 0.2 : -0.2), (corner & 2 ? 0.1 : -0.1), (corner & 4 ? 0.05 : -0.05)};
        bool near = true;
        for (int k = 0; k < 3; ++k) {
          const double e = x[3 + k] + R[3 * k] * s[0] + R[3 * k + 1] * s[1] + R[3 * k + 2] * s[2];
          near = near && std::fabs(world[3 * v + k] - e) <= tolerance(e);
        }
        if (near) match = corner;
      }
      ASSERT_GE(match, 0) << step << ": vertex " << v << " is no corner of the box";
      EXPECT_FALSE(seen[match]) << "corner " << match << " drawn twice";
      seen[match] = true;
    }
  }
}

// Viewers cull and light faces by their winding: outlines turn counter-clockwise, surface
// polygons are counter-clockwise seen from outside (their normal leaves the shape).
TEST(Display, PolygonsTurnOutward) {
  for (int d : {2, 3}) {
    SceneRun r;
    ASSERT_NO_FATAL_FAILURE(run_scene(r, "display_winding" + std::to_string(d),
                                      d == 2 ? display_scene_2d() : display_scene_3d()));
    const Mesh m = read_mesh(r.file);
    const auto p = read_as<double>(r.file, "/display/points", H5T_NATIVE_DOUBLE);
    auto at = [&](int v, int k) { return p[d * v + k]; };
    for (std::size_t c = 0; c < m.cells.size(); ++c) {
      const auto& cell = m.cells[c];
      const auto& vs = m.contactor_vertices[m.cell_contactor[c]];
      double n[3] = {0, 0, 0}, face[3] = {0, 0, 0}, centre[3] = {0, 0, 0};
      for (std::size_t i = 0; i < cell.size(); ++i) {  // Newell's normal
        const int a = cell[i], b = cell[(i + 1) % cell.size()];
        const double az = d == 3 ? at(a, 2) : 0, bz = d == 3 ? at(b, 2) : 0;
        n[0] += (at(a, 1) - at(b, 1)) * (az + bz);
        n[1] += (az - bz) * (at(a, 0) + at(b, 0));
        n[2] += (at(a, 0) - at(b, 0)) * (at(a, 1) + at(b, 1));
        for (int k = 0; k < d; ++k) face[k] += at(a, k) / cell.size();
      }
      for (int v : vs)
        for (int k = 0; k < d; ++k) centre[k] += at(v, k) / vs.size();
      if (d == 2) {
        EXPECT_GT(n[2], 0) << "2D cell " << c << " turns clockwise";
      } else if (vs.size() == cell.size()) {  // the plane's patch, alone: faces up (+z)
        EXPECT_GT(n[2], 0) << "plane patch faces down";
      } else {
        const double out = n[0] * (face[0] - centre[0]) + n[1] * (face[1] - centre[1]) + n[2] * (face[2] - centre[2]);
        EXPECT_GT(out, 0) << "3D cell " << c << " of contactor " << m.cell_contactor[c] << " faces inward";
      }
    }
  }
}

TEST(Display, PointsWritesNoDisplayData) {
  for (int d : {2, 3}) {
    SceneRun r;
    ASSERT_NO_FATAL_FAILURE(run_scene(r, "display_points" + std::to_string(d),
                                      d == 2 ? display_scene_2d("points") : display_scene_3d("points")));
    EXPECT_FALSE(h5_exists(r.file, "/display"));
    for (const char* step : {"00000000", "00000005", "00000010"}) {
      EXPECT_TRUE(h5_exists(r.file, frame(step, "position"))) << step;
      EXPECT_FALSE(h5_exists(r.file, frame(step, "display"))) << step;
    }
    std::ifstream x(r.dir / "out.xmf");
    std::stringstream s;
    s << x.rdbuf();
    EXPECT_EQ(s.str().find("Name=\"shapes\""), std::string::npos);
    EXPECT_EQ(s.str().find("/display"), std::string::npos);
  }
}

TEST(Display, UnknownDisplayValueIsAnInputError) {
  const fs::path dir = scratch_dir("display_bad");
  const fs::path scene = write_file(dir, "scene.json", display_scene_2d("meshes"));
  const Result res = run_moreau({"run", scene.string(), "--quiet"}, dir);
  EXPECT_EQ(res.code, 2);
  EXPECT_NE(res.err.find("/output/display"), std::string::npos) << res.err;
}
