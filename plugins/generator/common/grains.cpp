#include "grains.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <moreau/error.hpp>
#include <set>

namespace moreau::generate {

namespace {

std::string dump(const json& j) { return j.dump(); }

double positive(const json& o, const std::string& key, const std::string& ptr) {
  if (!o.contains(key)) throw InputError(ptr + "/" + key, "missing \"" + key + "\" (m, > 0)");
  if (!o[key].is_number() || !(o[key].get<double>() > 0))
    throw InputError(ptr + "/" + key, "expected a length > 0 (m), got " + dump(o[key]));
  return o[key].get<double>();
}

void only_keys(const json& o, const std::string& ptr, const std::vector<std::string>& keys) {
  for (auto it = o.begin(); it != o.end(); ++it)
    if (std::find(keys.begin(), keys.end(), it.key()) == keys.end()) {
      std::string list;
      for (const auto& k : keys) list += (list.empty() ? "" : ", ") + k;
      throw InputError(ptr + "/" + it.key(), "unknown key \"" + it.key() + "\"; valid keys: " + list);
    }
}

}  // namespace

void grain_params(Schema& s) {
  s.object("grain", "the grain: {\"shape\": \"disk\"|\"sphere\"|\"polygon\"|\"convex\", \"group\" (default \"grain\"), "
                    "\"sides\" (polygon, default 6), \"corners\" (convex, default 12)}");
  s.object("body", "keys every generated body gets (material, velocity, fixed, ...)").fallback(json::object());
  s.string("name", "bodies are named NAME_0, NAME_1, ...").fallback("grain");
}

GrainKind GrainKind::parse(const Params& p, const std::string& key, int dim) {
  const json& o = p.raw(key);
  const std::string ptr = p.pointer(key);
  if (!o.is_object()) throw InputError(ptr, "expected an object {\"shape\", \"group\", ...}, got " + dump(o));
  only_keys(o, ptr, {"shape", "group", "sides", "corners"});
  GrainKind g;
  if (!o.contains("shape") || !o["shape"].is_string())
    throw InputError(ptr + "/shape", "missing or invalid \"shape\": expected \"disk\", \"polygon\" (2D), \"sphere\" or \"convex\" (3D)");
  g.shape = o["shape"].get<std::string>();
  const bool two = g.shape == "disk" || g.shape == "polygon", three = g.shape == "sphere" || g.shape == "convex";
  if (!two && !three)
    throw InputError(ptr + "/shape", "unknown grain shape \"" + g.shape + "\": expected \"disk\", \"polygon\" (2D), \"sphere\" or \"convex\" (3D)");
  if ((dim == 2) != two)
    throw InputError(ptr + "/shape", "a \"" + g.shape + "\" grain does not exist in " + std::to_string(dim) + "D scenes");
  if (o.contains("group")) {
    if (!o["group"].is_string()) throw InputError(ptr + "/group", "expected a group name, got " + dump(o["group"]));
    g.group = o["group"].get<std::string>();
  }
  auto count = [&](const char* k, int lo, int hi, int& out) {
    if (!o.contains(k)) return;
    if (!o[k].is_number_integer() || o[k].get<int>() < lo || o[k].get<int>() > hi)
      throw InputError(ptr + "/" + k, "expected an integer from " + std::to_string(lo) + " to " + std::to_string(hi) +
                                          ", got " + dump(o[k]));
    out = o[k].get<int>();
  };
  count("sides", 3, 64, g.sides);
  count("corners", 4, 64, g.corners);
  return g;
}

json GrainKind::contactor(double r, Random& rng, bool turn) const {
  json c = {{"shape", shape}, {"group", group}};
  if (shape == "disk" || shape == "sphere") {
    c["radius"] = r;
  } else if (shape == "polygon") {
    const double a0 = turn ? rng.uniform(0, 2 * M_PI) : 0.0;
    json v = json::array();
    for (int k = 0; k < sides; ++k) {
      const double a = a0 + 2 * M_PI * k / sides;
      v.push_back({r * std::cos(a), r * std::sin(a)});
    }
    c["vertices"] = v;
  } else {  // convex: corners uniform on the sphere of radius r (all on the hull)
    json v = json::array();
    for (int k = 0; k < corners; ++k) {
      double x[3], n = 0;
      do {
        n = 0;
        for (double& xi : x) xi = rng.normal(), n += xi * xi;
      } while (n < 1e-12);
      n = std::sqrt(n);
      v.push_back({r * x[0] / n, r * x[1] / n, r * x[2] / n});
    }
    c["vertices"] = v;
  }
  return c;
}

SizeDistribution SizeDistribution::parse(const Params& p, const std::string& key) {
  SizeDistribution s;
  s.pointer = p.pointer(key);
  const json& o = p.raw(key);
  if (o.is_number()) {
    if (!(o.get<double>() > 0)) throw InputError(s.pointer, "expected a radius > 0 (m), got " + dump(o));
    s.a = o.get<double>();
    return s;
  }
  if (!o.is_object() || !o.contains("distribution") || !o["distribution"].is_string())
    throw InputError(s.pointer, "expected a radius (m) or {\"distribution\": \"uniform\"|\"list\"|\"lognormal\", ...}, got " + dump(o));
  s.kind = o["distribution"].get<std::string>();
  if (s.kind == "uniform") {
    only_keys(o, s.pointer, {"distribution", "min", "max"});
    s.a = positive(o, "min", s.pointer);
    s.b = positive(o, "max", s.pointer);
    if (s.b < s.a) throw InputError(s.pointer + "/max", "\"max\" is below \"min\"");
  } else if (s.kind == "list") {
    only_keys(o, s.pointer, {"distribution", "values", "fractions"});
    if (!o.contains("values") || !o["values"].is_array() || o["values"].empty())
      throw InputError(s.pointer + "/values", "expected a list of radii (m)");
    for (std::size_t i = 0; i < o["values"].size(); ++i) {
      const json& v = o["values"][i];
      if (!v.is_number() || !(v.get<double>() > 0))
        throw InputError(s.pointer + "/values/" + std::to_string(i), "expected a radius > 0 (m), got " + dump(v));
      s.values.push_back(v.get<double>());
    }
    if (o.contains("fractions")) {
      const json& f = o["fractions"];
      if (!f.is_array() || f.size() != s.values.size())
        throw InputError(s.pointer + "/fractions", "expected one fraction per value (" + std::to_string(s.values.size()) + ")");
      double sum = 0;
      for (std::size_t i = 0; i < f.size(); ++i) {
        if (!f[i].is_number() || f[i].get<double>() < 0)
          throw InputError(s.pointer + "/fractions/" + std::to_string(i), "expected a fraction >= 0, got " + dump(f[i]));
        s.fractions.push_back(f[i].get<double>());
        sum += f[i].get<double>();
      }
      if (std::fabs(sum - 1) > 1e-6)
        throw InputError(s.pointer + "/fractions", "the fractions add up to " + std::to_string(sum) + ", not 1");
    } else {
      s.fractions.assign(s.values.size(), 1.0 / static_cast<double>(s.values.size()));
    }
  } else if (s.kind == "lognormal") {
    only_keys(o, s.pointer, {"distribution", "median", "sigma", "min", "max"});
    s.a = positive(o, "median", s.pointer);
    if (!o.contains("sigma") || !o["sigma"].is_number() || o["sigma"].get<double>() < 0)
      throw InputError(s.pointer + "/sigma", "expected the standard deviation of ln r (>= 0)");
    s.b = o["sigma"].get<double>();
    s.lo = o.contains("min") ? positive(o, "min", s.pointer) : 0.0;
    s.hi = o.contains("max") ? positive(o, "max", s.pointer) : std::numeric_limits<double>::infinity();
    if (!(s.lo <= s.a && s.a <= s.hi)) throw InputError(s.pointer, "the median must lie within [min, max]");
  } else {
    throw InputError(s.pointer + "/distribution", "unknown distribution \"" + s.kind + "\": expected \"uniform\", \"list\" or \"lognormal\"");
  }
  return s;
}

std::vector<double> SizeDistribution::draw(std::size_t n, Random& rng) const {
  std::vector<double> r(n, a);
  if (kind == "uniform") {
    for (auto& x : r) x = rng.uniform(a, b);
  } else if (kind == "lognormal") {
    for (auto& x : r) {
      do x = a * std::exp(b * rng.normal());
      while (x < lo || x > hi);
    }
  } else if (kind == "list") {
    // Exact counts by largest remainders, then shuffled (Fisher–Yates).
    std::vector<std::size_t> count(values.size());
    std::vector<std::pair<double, std::size_t>> rest;
    std::size_t given = 0;
    for (std::size_t i = 0; i < values.size(); ++i) {
      const double want = fractions[i] * static_cast<double>(n);
      count[i] = static_cast<std::size_t>(std::floor(want));
      given += count[i];
      rest.emplace_back(-(want - std::floor(want)), i);
    }
    std::sort(rest.begin(), rest.end());
    for (std::size_t k = 0; given < n; ++k, ++given) ++count[rest[k % rest.size()].second];
    r.clear();
    for (std::size_t i = 0; i < values.size(); ++i) r.insert(r.end(), count[i], values[i]);
    for (std::size_t i = r.size(); i > 1; --i) std::swap(r[i - 1], r[static_cast<std::size_t>(rng.uniform() * static_cast<double>(i))]);
  }
  return r;
}

double SizeDistribution::largest() const {
  if (kind == "uniform") return b;
  if (kind == "list") return *std::max_element(values.begin(), values.end());
  if (kind == "lognormal") return std::isfinite(hi) ? hi : a * std::exp(6 * b);
  return a;
}

BodyTemplate BodyTemplate::parse(const Params& p, const json& scene) {
  BodyTemplate t;
  t.prefix = p.string("name");
  const json& keys = p.raw("body");
  if (!keys.is_object()) throw InputError(p.pointer("body"), "expected an object of body keys, got " + dump(keys));
  for (const char* k : {"name", "position", "contactors"})
    if (keys.contains(k))
      throw InputError(p.pointer("body") + "/" + k, std::string("\"") + k + "\" is set by the generator");
  t.keys = keys;
  // Names NAME_k must be new: a clash would be reported on a body the user never wrote.
  if (scene.contains("bodies") && scene["bodies"].is_array())
    for (const auto& b : scene["bodies"])
      if (b.is_object() && b.contains("name") && b["name"].is_string()) {
        const std::string n = b["name"].get<std::string>();
        if (n.size() > t.prefix.size() + 1 && n.compare(0, t.prefix.size() + 1, t.prefix + "_") == 0 &&
            n.find_first_not_of("0123456789", t.prefix.size() + 1) == std::string::npos)
          throw InputError(p.pointer("name"), "the scene already has a body named \"" + n +
                                                  "\": give this generator another \"name\" for its bodies");
      }
  return t;
}

json BodyTemplate::make(std::size_t index, const std::vector<double>& position, json contactor) const {
  json b = keys;
  b["name"] = prefix + "_" + std::to_string(index);
  b["position"] = position;
  b["contactors"] = json::array({std::move(contactor)});
  return b;
}

void BallGrid::cell_of(const double* x, long long c[3]) const {
  for (int k = 0; k < 3; ++k) c[k] = k < dim_ ? static_cast<long long>(std::floor(x[k] / cell_)) : 0;
}

void BallGrid::add(const double* x, double r) {
  long long c[3];
  cell_of(x, c);
  cells_[key(c)].push_back(r_.size());
  for (int k = 0; k < 3; ++k) x_.push_back(k < dim_ ? x[k] : 0.0);
  r_.push_back(r);
}

double BallGrid::gap(const double* x, double r) const {
  long long c[3];
  cell_of(x, c);
  double best = std::numeric_limits<double>::infinity();
  const int span = static_cast<int>(std::ceil(2 * r / cell_)) + 1;  // a ball up to cell/2 plus r
  const int sz = dim_ == 3 ? span : 0;
  for (int i = -span; i <= span; ++i)
    for (int j = -span; j <= span; ++j)
      for (int k = -sz; k <= sz; ++k) {
        const long long n[3] = {c[0] + i, c[1] + j, c[2] + k};
        auto it = cells_.find(key(n));
        if (it == cells_.end()) continue;
        for (std::size_t b : it->second) {
          double s = 0;
          for (int q = 0; q < dim_; ++q) s += (x[q] - x_[3 * b + q]) * (x[q] - x_[3 * b + q]);
          best = std::min(best, std::sqrt(s) - r - r_[b]);
        }
      }
  return best;
}

}  // namespace moreau::generate
