// `lattice`: grains on a regular array. 2D: "square", "triangular" (= "hexagonal": the
// hexagonal close packing of disks, rows offset by half a spacing); 3D: "cubic", "fcc"
// (square layers, each resting in the hollows of the one below: the cannonball stack),
// "hcp" (triangular layers stacked ABAB). `counts` grains along each axis from `origin` (the
// centre of the first grain), `spacing` between neighbours in a row (default 2·radius:
// touching), `row_spacing` between rows (2D) or layers (3D), by default each row resting
// on the one below; `fixed_rows`: the first rows are fixed bodies; `short_rows`: every other row (2D) or layer (3D) has one grain fewer per axis, so
// that the array fits a box of width counts·spacing. Grains that would overlap each other
// or the bodies named in `avoid` (default none: an array may touch its box) are an error.
#include <cmath>
#include <grains.hpp>
#include <moreau/error.hpp>
#include <moreau/generator.hpp>
#include <obstacles.hpp>

namespace {

using namespace moreau;
using namespace moreau::generate;

class Lattice : public Generator {
 public:
  static Schema schema() {
    Schema s;
    s.string("lattice", "the array").one_of({"square", "triangular", "hexagonal", "cubic", "fcc", "hcp"});
    s.array("counts", "grains along each axis, [nx, ny] (2D) or [nx, ny, nz] (3D)");
    s.vector("origin", "centre of the first grain", length::dimension).units("m");
    s.number("radius", "grain (circum)radius").units("m").gt(0);
    s.number("spacing", "distance between neighbours in a row (default: 2 radius)").units("m").gt(0).optional();
    s.number("row_spacing", "distance between rows (2D) or layers (3D); default: each row resting on the one below "
                            "(square and cubic: the spacing)").units("m").gt(0).optional();
    s.integer("fixed_rows", "the first rows (2D) or layers (3D) are fixed bodies, e.g. a rough floor").min(0).fallback(0);
    s.boolean("short_rows", "every other row or layer has one grain fewer per axis").fallback(false);
    s.array("avoid", "names of the scene's bodies the grains must not overlap (default: none, so that an array may "
                     "touch its box)").optional();
    grain_params(s);
    s.integer("seed", "random seed (convex grains' corners)").min(0).fallback(1);
    return s;
  }
  static constexpr const char* doc = "grains on a regular array: square, triangular (2D); cubic, fcc, hcp (3D)";

  Lattice(const Params& p, const BuildContext& ctx) : p_(p), dim_(ctx.dimension) {}

  std::vector<nlohmann::json> generate(const GeneratorInput& in) override {
    const int d = dim_;
    const std::string kind = p_.string("lattice");
    const bool two = kind == "square" || kind == "triangular" || kind == "hexagonal";
    if (two != (d == 2))
      throw p_.error("lattice", "lattice \"" + kind + "\" is for " + std::string(two ? "2D" : "3D") + " scenes");
    const json& counts = p_.raw("counts");
    if (!counts.is_array() || counts.size() != static_cast<std::size_t>(d))
      throw p_.error("counts", "expected " + std::to_string(d) + " counts of grains, got " + counts.dump());
    long n[3] = {1, 1, 1};
    for (int k = 0; k < d; ++k) {
      if (!counts[k].is_number_integer() || counts[k].get<long>() < 1 || counts[k].get<long>() > 100000)
        throw InputError(p_.pointer("counts") + "/" + std::to_string(k), "expected a count of grains (1 to 100000), got " + counts[k].dump());
      n[k] = counts[k].get<long>();
    }
    const double r = p_.number("radius");
    const double s = p_.has("spacing") ? p_.number("spacing") : 2 * r;
    const bool short_rows = p_.boolean("short_rows");
    // Rows (layers) rest on the ones below: with spacing s and radius r a grain touches the
    // two (three, four) below it at height √((2r)² − c²), c the horizontal distance to them
    // (s/2 triangular, s/√2 fcc, s/√3 hcp); for s = 2r these are the close packings.
    double row = s;  // square, cubic: stacked
    double c2 = -1;  // squared horizontal distance to the grains below
    if (kind == "triangular" || kind == "hexagonal") c2 = s * s / 4;
    if (kind == "fcc") c2 = s * s / 2;
    if (kind == "hcp") c2 = s * s / 3;
    if (p_.has("row_spacing")) {
      row = p_.number("row_spacing");
    } else if (c2 >= 0) {
      if (c2 >= 4 * r * r)
        throw p_.error("spacing", "with this spacing the rows cannot rest on each other: give \"row_spacing\"");
      row = std::sqrt(4 * r * r - c2);
    }
    const auto origin = p_.vector("origin");

    // Positions, in row order (x fastest), and whether each is in a fixed row.
    std::vector<std::vector<double>> at;
    std::vector<char> fixed;
    const long fixed_rows = p_.integer("fixed_rows");
    long layer = 0;
    auto push = [&](double x, double y, double z) {
      std::vector<double> q{origin[0] + x, origin[1] + y};
      if (d == 3) q.push_back(origin[2] + z);
      at.push_back(q);
      fixed.push_back(layer < fixed_rows ? 1 : 0);
    };
    if (d == 2) {
      const bool shifted = kind != "square";
      for (long j = 0; j < n[1]; ++j) {
        layer = j;
        const bool odd = shifted && j % 2 == 1;
        const long m = odd && short_rows ? n[0] - 1 : n[0];
        for (long i = 0; i < m; ++i) push(i * s + (odd ? s / 2 : 0.0), j * row, 0);
      }
    } else {
      const double h = s * std::sqrt(3.0) / 2;  // hcp: rows within a layer
      for (long k = 0; k < n[2]; ++k) {
        layer = k;
        const bool odd = k % 2 == 1;
        const long mx = odd && short_rows ? n[0] - 1 : n[0], my = odd && short_rows ? n[1] - 1 : n[1];
        for (long j = 0; j < my; ++j)
          for (long i = 0; i < mx; ++i) {
            if (kind == "cubic") push(i * s, j * s, k * row);
            else if (kind == "fcc") push(i * s + (odd ? s / 2 : 0.0), j * s + (odd ? s / 2 : 0.0), k * row);
            else push(i * s + (j % 2 ? s / 2 : 0.0) + (odd ? s / 2 : 0.0), j * h + (odd ? h / 3 : 0.0), k * row);
          }
      }
    }

    // Neither overlapping each other nor the bodies to avoid (touching is fine: rounding).
    const double slack = 1e-9 * r;
    BallGrid grid(d, 2 * r);
    Obstacles avoid = Obstacles::parse(p_, "avoid", in.scene, d, false);
    for (std::size_t i = 0; i < at.size(); ++i) {
      const double g = grid.gap(at[i].data(), r);
      if (g < -slack)
        throw p_.error("", "the lattice's grains overlap (grain " + std::to_string(i) + " is " + std::to_string(-g) +
                               " m into a neighbour): make \"spacing\" or \"row_spacing\" at least the grains' diameter");
      const double a = avoid.gap(at[i].data(), r);
      if (a < -slack)
        throw p_.error("avoid", "grain " + std::to_string(i) + " of the lattice overlaps a body to avoid by " +
                                    std::to_string(-a) + " m: move \"origin\" or change \"counts\"");
      grid.add(at[i].data(), r);
    }

    const GrainKind grain = GrainKind::parse(p_, "grain", d);
    const BodyTemplate body = BodyTemplate::parse(p_, in.scene);
    Random rng(static_cast<std::uint64_t>(p_.integer("seed")));
    std::vector<nlohmann::json> out;
    for (std::size_t i = 0; i < at.size(); ++i) {
      out.push_back(body.make(i, at[i], grain.contactor(r, rng, false)));
      if (fixed[i]) out.back()["fixed"] = true;
    }
    return out;
  }

 private:
  Params p_;
  int dim_;
};

MOREAU_REGISTER(Lattice, "lattice")

}  // namespace

MOREAU_PLUGIN_LIBRARY("moreau_generator_lattice")
