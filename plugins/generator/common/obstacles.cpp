#include "obstacles.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <moreau/error.hpp>

namespace moreau::generate {

using nlohmann::json;

namespace {

/// n numbers at key `k` of object o (or `fallback` when absent).
std::vector<double> numbers(const json& o, const char* k, std::size_t n, const std::string& ptr, const std::string& why,
                            std::vector<double> fallback) {
  if (!o.contains(k)) {
    // An empty fallback marks a key the shape needs (radius, length, size…): callers index it.
    if (fallback.empty())
      throw InputError(ptr + "/" + k, "missing: expected " + std::to_string(n) +
                                          " number(s) to keep clear of this body (" + why + ")");
    return fallback;
  }
  const json& v = o[k];
  if (v.is_number() && n == 1) return {v.get<double>()};
  if (!v.is_array() || v.size() != n || !std::all_of(v.begin(), v.end(), [](const json& x) { return x.is_number(); }))
    throw InputError(ptr + "/" + k, "expected " + std::to_string(n) + " number(s) to keep clear of this body (" + why + ")");
  return v.get<std::vector<double>>();
}

void matrix(int dim, const std::vector<double>& rot, double m[9]) {
  if (dim == 2) {
    const double c = std::cos(rot[0]), s = std::sin(rot[0]);
    const double r[9] = {c, -s, 0, s, c, 0, 0, 0, 1};
    std::copy(r, r + 9, m);
    return;
  }
  double w = rot[0], x = rot[1], y = rot[2], z = rot[3];
  const double n = std::sqrt(w * w + x * x + y * y + z * z);
  w /= n, x /= n, y /= n, z /= n;
  const double r[9] = {1 - 2 * (y * y + z * z), 2 * (x * y - w * z),     2 * (x * z + w * y),
                       2 * (x * y + w * z),     1 - 2 * (x * x + z * z), 2 * (y * z - w * x),
                       2 * (x * z - w * y),     2 * (y * z + w * x),     1 - 2 * (x * x + y * y)};
  std::copy(r, r + 9, m);
}

void mul(const double a[9], const double b[9], double out[9]) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) out[3 * i + j] = a[3 * i] * b[j] + a[3 * i + 1] * b[3 + j] + a[3 * i + 2] * b[6 + j];
}

/// World point of shape-frame point s: p + R s.
void place(const double p[3], const double R[9], const double s[3], double out[3]) {
  for (int i = 0; i < 3; ++i) out[i] = p[i] + R[3 * i] * s[0] + R[3 * i + 1] * s[1] + R[3 * i + 2] * s[2];
}

double segment_distance(const double* x, const double* a, const double* b, int d) {
  double ab2 = 0, t = 0;
  for (int k = 0; k < d; ++k) ab2 += (b[k] - a[k]) * (b[k] - a[k]), t += (x[k] - a[k]) * (b[k] - a[k]);
  t = ab2 > 0 ? std::clamp(t / ab2, 0.0, 1.0) : 0.0;
  double s = 0;
  for (int k = 0; k < d; ++k) {
    const double e = x[k] - (a[k] + t * (b[k] - a[k]));
    s += e * e;
  }
  return std::sqrt(s);
}

}  // namespace

Obstacles Obstacles::parse(const Params& p, const std::string& key, const json& scene, int dim, bool all_by_default) {
  Obstacles o;
  o.dim_ = dim;
  const json spec = p.has(key) ? p.raw(key) : all_by_default ? json("all") : json::array();
  const std::string ptr = p.pointer(key);
  const json& bodies = scene.contains("bodies") && scene["bodies"].is_array() ? scene["bodies"] : json::array();
  const std::string why = "needed by " + ptr;
  if (spec.is_string() && spec == "all") {
    for (std::size_t i = 0; i < bodies.size(); ++i) o.add_body(bodies[i], "/bodies/" + std::to_string(i), why);
    return o;
  }
  if (!spec.is_array()) throw InputError(ptr, "expected a list of body names, got " + spec.dump());
  for (std::size_t i = 0; i < spec.size(); ++i) {
    const std::string ip = ptr + "/" + std::to_string(i);
    if (!spec[i].is_string()) throw InputError(ip, "expected a body name, got " + spec[i].dump());
    bool found = false;
    for (std::size_t b = 0; b < bodies.size(); ++b)
      if (bodies[b].is_object() && bodies[b].value("name", json()) == spec[i]) {
        o.add_body(bodies[b], "/bodies/" + std::to_string(b), why);
        found = true;
      }
    if (!found) throw InputError(ip, "no body named " + spec[i].dump() + " in the scene (before this generator)");
  }
  return o;
}

void Obstacles::add_body(const json& body, const std::string& ptr, const std::string& why) {
  if (!body.is_object()) throw InputError(ptr, "expected a body object (" + why + ")");
  const int d = dim_;
  const auto pos = numbers(body, "position", static_cast<std::size_t>(d), ptr, why, std::vector<double>(d, 0.0));
  const double p[3] = {pos[0], pos[1], d == 3 ? pos[2] : 0.0};
  double Rb[9];
  matrix(d, d == 2 ? numbers(body, "angle", 1, ptr, why, {0.0}) : numbers(body, "orientation", 4, ptr, why, {1, 0, 0, 0}), Rb);
  if (!body.contains("contactors")) return;
  const json& cs = body["contactors"];
  if (!cs.is_array()) throw InputError(ptr + "/contactors", "expected a list of contactors (" + why + ")");
  for (std::size_t i = 0; i < cs.size(); ++i) {
    const json& c = cs[i];
    const std::string cp = ptr + "/contactors/" + std::to_string(i);
    if (!c.is_object() || !c.contains("shape") || !c["shape"].is_string())
      throw InputError(cp, "expected a contactor with a \"shape\" (" + why + ")");
    const auto off = numbers(c, "offset", static_cast<std::size_t>(d), cp, why, std::vector<double>(d, 0.0));
    double Rc[9], R[9], o[3];
    matrix(d, d == 2 ? numbers(c, "angle", 1, cp, why, {0.0}) : numbers(c, "orientation", 4, cp, why, {1, 0, 0, 0}), Rc);
    mul(Rb, Rc, R);
    const double offset[3] = {off[0], off[1], d == 3 ? off[2] : 0.0};
    place(p, Rb, offset, o);  // the shape's origin in the world
    const std::string shape = c["shape"].get<std::string>();
    Item it;
    if (shape == "disk" || shape == "sphere") {
      it.kind = Item::ball;
      std::copy(o, o + 3, it.c);
      it.r = numbers(c, "radius", 1, cp, why, {})[0];
    } else if (shape == "segment") {
      it.kind = Item::capsule;
      const double L = numbers(c, "length", 1, cp, why, {})[0], t = numbers(c, "thickness", 1, cp, why, {})[0];
      const double a[3] = {-L / 2, 0, 0}, b[3] = {L / 2, 0, 0};
      place(o, R, a, it.c);
      place(o, R, b, it.d);
      it.r = t / 2;
    } else if (shape == "plane") {
      it.kind = Item::halfspace;
      const auto n = numbers(c, "normal", 3, cp, why, {0, 0, 1});
      const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
      std::copy(o, o + 3, it.c);
      for (int k = 0; k < 3; ++k) it.d[k] = (R[3 * k] * n[0] + R[3 * k + 1] * n[1] + R[3 * k + 2] * n[2]) / len;
    } else if (shape == "box") {
      it.kind = Item::box;
      const auto s = numbers(c, "size", 3, cp, why, {});
      std::copy(o, o + 3, it.c);
      for (int k = 0; k < 3; ++k) it.d[k] = s[static_cast<std::size_t>(k)] / 2;
      std::copy(R, R + 9, it.rot);
    } else if (shape == "polygon" || shape == "convex") {
      const json& vs = c.contains("vertices") ? c["vertices"] : json();
      if (!vs.is_array() || vs.size() < 3) throw InputError(cp + "/vertices", "expected the shape's corners (" + why + ")");
      std::vector<double> w;
      for (std::size_t k = 0; k < vs.size(); ++k) {
        const auto q = numbers(json{{"v", vs[k]}}, "v", static_cast<std::size_t>(d), cp + "/vertices/" + std::to_string(k), why, {});
        const double s[3] = {q[0], q[1], d == 3 ? q[2] : 0.0};
        double x[3];
        place(o, R, s, x);
        w.insert(w.end(), x, x + d);
      }
      if (shape == "polygon") {
        it.kind = Item::polygon;
        it.v = w;
      } else {  // the bounding sphere about the corners' mean: conservative
        it.kind = Item::ball;
        const std::size_t n = w.size() / 3;
        for (std::size_t k = 0; k < n; ++k)
          for (int q = 0; q < 3; ++q) it.c[q] += w[3 * k + q] / static_cast<double>(n);
        for (std::size_t k = 0; k < n; ++k) {
          double s = 0;
          for (int q = 0; q < 3; ++q) s += (w[3 * k + q] - it.c[q]) * (w[3 * k + q] - it.c[q]);
          it.r = std::max(it.r, std::sqrt(s));
        }
      }
    } else {
      throw InputError(cp + "/shape", "a generator cannot keep clear of shape \"" + shape + "\" (" + why +
                                          "): list the bodies to avoid by name, without this one");
    }
    items_.push_back(std::move(it));
  }
}

void Obstacles::move_small_balls(BallGrid& grid, double max_radius) {
  std::vector<Item> keep;
  for (auto& it : items_) {
    if (it.kind == Item::ball && it.r <= max_radius) grid.add(it.c, it.r);
    else keep.push_back(std::move(it));
  }
  items_ = std::move(keep);
}

double Obstacles::gap(const double* x, double r) const {
  double best = std::numeric_limits<double>::infinity();
  for (const auto& it : items_) best = std::min(best, item_gap(it, x, r));
  return best;
}

double Obstacles::item_gap(const Item& it, const double* x, double r) const {
  const int d = dim_;
  switch (it.kind) {
    case Item::ball: {
      double s = 0;
      for (int k = 0; k < d; ++k) s += (x[k] - it.c[k]) * (x[k] - it.c[k]);
      return std::sqrt(s) - it.r - r;
    }
    case Item::capsule: return segment_distance(x, it.c, it.d, d) - it.r - r;
    case Item::halfspace: {
      double s = 0;
      for (int k = 0; k < 3; ++k) s += it.d[k] * ((k < d ? x[k] : 0.0) - it.c[k]);
      return s - r;
    }
    case Item::box: {
      double q[3], out = 0, in = -std::numeric_limits<double>::infinity();
      for (int k = 0; k < 3; ++k) {
        double s = 0;
        for (int j = 0; j < 3; ++j) s += it.rot[3 * j + k] * (x[j] - it.c[j]);
        q[k] = std::fabs(s) - it.d[k];
        out += std::max(q[k], 0.0) * std::max(q[k], 0.0);
        in = std::max(in, q[k]);
      }
      return std::sqrt(out) + std::min(in, 0.0) - r;
    }
    case Item::polygon: {
      const std::size_t n = it.v.size() / 2;
      double area = 0;
      for (std::size_t k = 0; k < n; ++k) {
        const double* a = &it.v[2 * k];
        const double* b = &it.v[2 * ((k + 1) % n)];
        area += a[0] * b[1] - a[1] * b[0];
      }
      const double orient = area >= 0 ? 1.0 : -1.0;
      double inside = -std::numeric_limits<double>::infinity(), near = std::numeric_limits<double>::infinity();
      for (std::size_t k = 0; k < n; ++k) {
        const double* a = &it.v[2 * k];
        const double* b = &it.v[2 * ((k + 1) % n)];
        const double ex = b[0] - a[0], ey = b[1] - a[1], len = std::hypot(ex, ey);
        inside = std::max(inside, orient * (ey * (x[0] - a[0]) - ex * (x[1] - a[1])) / len);  // outward distance
        near = std::min(near, segment_distance(x, a, b, 2));
      }
      return (inside <= 0 ? inside : near) - r;
    }
  }
  return std::numeric_limits<double>::infinity();
}

}  // namespace moreau::generate
