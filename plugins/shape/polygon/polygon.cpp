// `polygon` (2D): a convex polygon given by its `vertices` in the body frame (either
// turning direction; stored counter-clockwise). Blocks, bricks, grains of any outline.
#include <algorithm>
#include <convex.hpp>
#include <display.hpp>
#include <moreau/shape.hpp>
#include <stdexcept>

namespace {
using namespace moreau;

std::vector<double> parse(const Params& p) {
  const auto& raw = p.raw("vertices");
  std::vector<std::array<double, 2>> v;
  for (std::size_t i = 0; i < raw.size(); ++i) {
    const auto& x = raw[i];
    if (!x.is_array() || x.size() != 2 || !x[0].is_number() || !x[1].is_number())
      throw InputError(p.pointer("vertices") + "/" + std::to_string(i), "expected a vertex [x, y]");
    v.push_back({x[0].get<double>(), x[1].get<double>()});
  }
  std::vector<geom::V2> ccw;
  try {
    ccw = geom::convex_polygon(v);
  } catch (const std::invalid_argument& e) {
    throw p.error("vertices", std::string("degenerate polygon: ") + e.what());
  }
  std::vector<double> g{static_cast<double>(ccw.size())};
  for (const auto& q : ccw) g.insert(g.end(), {q.x, q.y});
  return g;
}

class Polygon : public Shape {
 public:
  static Schema schema() {
    Schema s;
    s.array("vertices", "convex outline in the body frame, [[x, y], …], at least 3 corners").units("m");
    s.dimensions({2});
    return s;
  }
  static constexpr const char* doc = "convex polygon (2D)";
  Polygon(const Params& p, const BuildContext&) : g_(parse(p)) {}
  const char* shape_name() const override { return "polygon"; }
  const std::vector<double>& geometry() const override { return g_; }
  MassProperties mass_properties() const override {
    std::vector<geom::V2> v;
    for (int i = 0; i < static_cast<int>(g_[0]); ++i) v.push_back({g_[1 + 2 * i], g_[2 + 2 * i]});
    return geom::polygon_mass(v);
  }
  void bounds(int, const Pose& p, double lo[3], double hi[3]) const override {
    const geom::Polygon w = geom::polygon_at(g_, p);
    lo[0] = lo[1] = 1e300;
    hi[0] = hi[1] = -1e300;
    for (const auto& q : w.v) {
      lo[0] = std::min(lo[0], q.x), hi[0] = std::max(hi[0], q.x);
      lo[1] = std::min(lo[1], q.y), hi[1] = std::max(hi[1], q.y);
    }
    lo[2] = hi[2] = 0;
  }
  double half_width(int) const override {
    std::vector<geom::V2> v;
    for (int i = 0; i < static_cast<int>(g_[0]); ++i) v.push_back({g_[1 + 2 * i], g_[2 + 2 * i]});
    return geom::polygon_half_width(v);
  }
  DisplayMesh display_mesh(double) const override {
    return geom::outline_display(std::vector<double>(g_.begin() + 1, g_.end()));
  }

 private:
  std::vector<double> g_;
};
MOREAU_REGISTER(Polygon, "polygon")
}  // namespace
MOREAU_PLUGIN_LIBRARY("moreau_shape_polygon")
