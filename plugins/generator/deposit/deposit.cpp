// `deposit`: a random loose deposit of `count` grains (disks, spheres, regular polygons,
// convex polyhedra) whose sizes follow `size` (a radius, or a uniform, listed or lognormal
// distribution), placed without overlap in a `container` — a box, or a cylinder (2D: a
// disk) — and clear of the scene's bodies (`avoid`, by default every body listed before:
// walls, a floor, earlier generators' grains). Random sequential addition: the largest
// grains first, each at uniformly drawn positions until one is free, at most `attempts`
// draws each. A deposit that does not fit is an error saying how many grains were placed;
// random placement fills at most about 55 % of an area (2D) or 38 % of a volume (3D), so
// a loose deposit is usually made in a container a few times the settled sample's height
// and left to fall under gravity. Seeded: same parameters, same grains, bit for bit.
#include <algorithm>
#include <cmath>
#include <grains.hpp>
#include <moreau/error.hpp>
#include <moreau/generator.hpp>
#include <numeric>
#include <obstacles.hpp>

namespace {

using namespace moreau;
using namespace moreau::generate;

/// Where grain centres may go, for a grain of radius r.
struct Container {
  bool cylinder = false;
  double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};  // box
  double c[3] = {0, 0, 0}, radius = 0, height = 0;
  int axis = 2;
  double volume(int d) const {
    if (!cylinder) {
      double v = 1;
      for (int k = 0; k < d; ++k) v *= hi[k] - lo[k];
      return v;
    }
    return d == 2 ? M_PI * radius * radius : M_PI * radius * radius * height;
  }
  /// Draws a centre for radius r; false when r does not fit at all.
  bool draw(int d, double r, Random& rng, double* x) const {
    if (!cylinder) {
      for (int k = 0; k < d; ++k) {
        if (hi[k] - lo[k] < 2 * r) return false;
        x[k] = rng.uniform(lo[k] + r, hi[k] - r);
      }
      return true;
    }
    const double R = radius - r;
    if (R < 0 || (d == 3 && height < 2 * r)) return false;
    int plane[2] = {0, 1};
    if (d == 3) plane[0] = axis == 0 ? 1 : 0, plane[1] = axis == 2 ? 1 : 2;
    double u, v;
    do u = rng.uniform(-1, 1), v = rng.uniform(-1, 1);
    while (u * u + v * v > 1);
    x[plane[0]] = c[plane[0]] + R * u;
    x[plane[1]] = c[plane[1]] + R * v;
    if (d == 3) x[axis] = c[axis] + rng.uniform(r, height - r);
    return true;
  }
};

Container parse_container(const Params& p, int d) {
  const nlohmann::json& o = p.raw("container");
  const std::string ptr = p.pointer("container");
  auto numbers = [&](const nlohmann::json& obj, const char* key, const std::string& at, int n) {
    if (!obj.contains(key) || !obj[key].is_array() || obj[key].size() != static_cast<std::size_t>(n) ||
        !std::all_of(obj[key].begin(), obj[key].end(), [](const nlohmann::json& x) { return x.is_number(); }))
      throw InputError(at + "/" + key, "expected " + std::to_string(n) + " numbers (m)");
    return obj[key].get<std::vector<double>>();
  };
  Container c;
  if (o.is_object() && o.size() == 1 && o.contains("box") && o["box"].is_object()) {
    const std::string bp = ptr + "/box";
    const auto a = numbers(o["box"], "min", bp, d), b = numbers(o["box"], "max", bp, d);
    for (auto it = o["box"].begin(); it != o["box"].end(); ++it)
      if (it.key() != "min" && it.key() != "max") throw InputError(bp + "/" + it.key(), "unknown key \"" + it.key() + "\": a box has \"min\" and \"max\"");
    for (int k = 0; k < d; ++k) {
      c.lo[k] = a[static_cast<std::size_t>(k)];
      c.hi[k] = b[static_cast<std::size_t>(k)];
      if (!(c.lo[k] < c.hi[k])) throw InputError(bp + "/max/" + std::to_string(k), "the box is empty: max must exceed min");
    }
    return c;
  }
  if (o.is_object() && o.size() == 1 && o.contains("cylinder") && o["cylinder"].is_object()) {
    const std::string cp = ptr + "/cylinder";
    const auto& y = o["cylinder"];
    c.cylinder = true;
    const auto ctr = numbers(y, "center", cp, d);
    for (int k = 0; k < d; ++k) c.c[k] = ctr[static_cast<std::size_t>(k)];
    for (auto it = y.begin(); it != y.end(); ++it) {
      const bool ok = it.key() == "center" || it.key() == "radius" || (d == 3 && (it.key() == "height" || it.key() == "axis"));
      if (!ok)
        throw InputError(cp + "/" + it.key(), "unknown key \"" + it.key() + "\": a cylinder has \"center\", \"radius\"" +
                                                  std::string(d == 3 ? ", \"height\" and \"axis\"" : " (2D: a disk)"));
    }
    if (!y.contains("radius") || !y["radius"].is_number() || !(y["radius"].get<double>() > 0))
      throw InputError(cp + "/radius", "expected the cylinder's radius (m, > 0)");
    c.radius = y["radius"].get<double>();
    if (d == 3) {
      if (!y.contains("height") || !y["height"].is_number() || !(y["height"].get<double>() > 0))
        throw InputError(cp + "/height", "expected the cylinder's height (m, > 0) along its axis from \"center\" (the base's centre)");
      c.height = y["height"].get<double>();
      const std::string ax = y.value("axis", std::string("z"));
      if (ax != "x" && ax != "y" && ax != "z") throw InputError(cp + "/axis", "expected \"x\", \"y\" or \"z\"");
      c.axis = ax[0] - 'x';
    }
    return c;
  }
  throw InputError(ptr, "expected {\"box\": {\"min\": [...], \"max\": [...]}} or {\"cylinder\": {\"center\", \"radius\"" +
                            std::string(d == 3 ? ", \"height\", \"axis\"" : "") + "}}, got " + o.dump());
}

class Deposit : public Generator {
 public:
  static Schema schema() {
    Schema s;
    s.integer("count", "number of grains").min(1).max(10000000);
    s.number("radius", "grain (circum)radius, the same for all (or give \"size\")").units("m").gt(0).optional();
    s.object("size", "grain (circum)radii: {\"distribution\": \"uniform\", \"min\", \"max\"}, "
                     "{\"distribution\": \"list\", \"values\", \"fractions\"} or {\"distribution\": \"lognormal\", "
                     "\"median\", \"sigma\", \"min\", \"max\"} (m)")
        .optional();
    s.object("container", "{\"box\": {\"min\", \"max\"}} or {\"cylinder\": {\"center\", \"radius\"[, \"height\", "
                          "\"axis\"]}} (2D: a disk)");
    s.array("avoid", "names of the scene's bodies the grains keep clear of (default: every body listed before)").optional();
    grain_params(s);
    s.integer("seed", "random seed").min(0).fallback(1);
    s.integer("attempts", "positions drawn per grain before giving up").min(1).max(100000000).fallback(1000);
    s.boolean("turn", "polygons turned by a random angle").fallback(true);
    return s;
  }
  static constexpr const char* doc = "random loose deposit of grains with a size distribution in a box or a cylinder";

  Deposit(const Params& p, const BuildContext& ctx) : p_(p), dim_(ctx.dimension) {
    if (p.has("radius") == p.has("size"))
      throw p.error(p.has("size") ? "size" : "", "give either \"radius\" (one size) or \"size\" (a distribution)");
  }

  std::vector<nlohmann::json> generate(const GeneratorInput& in) override {
    const int d = dim_;
    const std::size_t n = static_cast<std::size_t>(p_.integer("count"));
    const GrainKind grain = GrainKind::parse(p_, "grain", d);
    const SizeDistribution size = SizeDistribution::parse(p_, p_.has("size") ? "size" : "radius");
    const Container box = parse_container(p_, d);
    const BodyTemplate body = BodyTemplate::parse(p_, in.scene);
    Obstacles avoid = Obstacles::parse(p_, "avoid", in.scene, d, true);
    Random rng(static_cast<std::uint64_t>(p_.integer("seed")));
    const std::vector<double> radius = size.draw(n, rng);
    const double biggest = *std::max_element(radius.begin(), radius.end());
    BallGrid grid(d, 2 * biggest);
    avoid.move_small_balls(grid, biggest);

    // Largest first (ties in grain order): small grains fill what the large ones leave.
    std::vector<std::size_t> order(n);
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return radius[a] > radius[b]; });
    const long attempts = p_.integer("attempts");
    std::vector<std::vector<double>> at(n);
    for (std::size_t placed = 0; placed < n; ++placed) {
      const std::size_t i = order[placed];
      const double r = radius[i];
      double x[3] = {0, 0, 0};
      bool ok = false;
      for (long t = 0; t < attempts && !ok; ++t) {
        if (!box.draw(d, r, rng, x)) break;
        ok = grid.gap(x, r) >= 0 && avoid.gap(x, r) >= 0;
      }
      if (!ok) {
        double solid = 0;
        for (double q : radius) solid += d == 2 ? M_PI * q * q : 4.0 / 3.0 * M_PI * q * q * q;
        char fill[64];
        std::snprintf(fill, sizeof fill, "%.0f%%", 100 * solid / box.volume(d));
        throw p_.error("count", "placed " + std::to_string(placed) + " of " + std::to_string(n) +
                                    " grains without overlap: the next (radius " + std::to_string(r) + " m) found no free place in " +
                                    std::to_string(attempts) + " attempts. The grains would fill " + fill +
                                    " of the container; random placement fills at most about " + (d == 2 ? "55" : "38") +
                                    "%: make the container larger (taller), or the grains fewer or smaller");
      }
      grid.add(x, r);
      at[i].assign(x, x + d);
    }
    std::vector<nlohmann::json> out;
    const bool turn = p_.boolean("turn");
    for (std::size_t i = 0; i < n; ++i) out.push_back(body.make(i, at[i], grain.contactor(radius[i], rng, turn)));
    return out;
  }

 private:
  Params p_;
  int dim_;
};

MOREAU_REGISTER(Deposit, "deposit")

}  // namespace

MOREAU_PLUGIN_LIBRARY("moreau_generator_deposit")
