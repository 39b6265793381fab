// `convex` (3D): the convex hull of `vertices` (body frame), which must all be corners of
// it. The hull is computed once at build time (O(n⁴): up to 64 vertices).
#include <algorithm>
#include <convex.hpp>
#include <display.hpp>
#include <moreau/shape.hpp>
#include <stdexcept>

namespace {
using namespace moreau;

struct Built {
  std::vector<double> geometry;
  geom::Polyhedron body_frame;
};

Built build(const Params& p) {
  const auto& raw = p.raw("vertices");
  if (raw.size() > 64) throw p.error("vertices", "at most 64 vertices, got " + std::to_string(raw.size()));
  std::vector<geom::V3> v;
  for (std::size_t i = 0; i < raw.size(); ++i) {
    const auto& x = raw[i];
    if (!x.is_array() || x.size() != 3 || !x[0].is_number() || !x[1].is_number() || !x[2].is_number())
      throw InputError(p.pointer("vertices") + "/" + std::to_string(i), "expected a vertex [x, y, z]");
    v.push_back({x[0].get<double>(), x[1].get<double>(), x[2].get<double>()});
  }
  Built b;
  try {
    b.body_frame.faces = geom::hull_faces(v);
  } catch (const std::invalid_argument& e) {
    throw p.error("vertices", std::string("degenerate convex shape: ") + e.what());
  }
  b.body_frame.v = v;
  b.body_frame.finish();
  b.geometry.push_back(static_cast<double>(v.size()));
  for (const auto& q : v) b.geometry.insert(b.geometry.end(), {q.x, q.y, q.z});
  b.geometry.push_back(static_cast<double>(b.body_frame.faces.size()));
  for (const auto& f : b.body_frame.faces) {
    b.geometry.push_back(static_cast<double>(f.size()));
    for (int i : f) b.geometry.push_back(i);
  }
  return b;
}

class Convex : public Shape {
 public:
  static Schema schema() {
    Schema s;
    s.array("vertices", "corners in the body frame, [[x, y, z], …], 4 to 64 (the hull is computed)").units("m");
    s.dimensions({3});
    return s;
  }
  static constexpr const char* doc = "convex polyhedron from its corners (3D)";
  Convex(const Params& p, const BuildContext&) : b_(build(p)) {}
  const char* shape_name() const override { return "convex"; }
  const std::vector<double>& geometry() const override { return b_.geometry; }
  MassProperties mass_properties() const override { return geom::polyhedron_mass(b_.body_frame); }
  void bounds(int, const Pose& p, double lo[3], double hi[3]) const override {
    for (int k = 0; k < 3; ++k) lo[k] = 1e300, hi[k] = -1e300;
    for (const auto& v : b_.body_frame.v) {
      const geom::V3 w = geom::rotate(p.rotation, v);
      const double x[3] = {p.position[0] + w.x, p.position[1] + w.y, p.position[2] + w.z};
      for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], x[k]), hi[k] = std::max(hi[k], x[k]);
    }
  }
  double half_width(int) const override { return geom::polyhedron_half_width(b_.body_frame); }
  /// The hull computed at build time: its corners and (merged, flat) faces.
  DisplayMesh display_mesh(double) const override { return geom::polyhedron_display(b_.geometry); }

 private:
  Built b_;
};
MOREAU_REGISTER(Convex, "convex")
}  // namespace
MOREAU_PLUGIN_LIBRARY("moreau_shape_convex")
