#include "analysis_tools.hpp"

#include <cmath>
#include <moreau/error.hpp>

namespace moreau::analysis {

int axis_of(const nlohmann::json& v, int dim, const std::string& ptr) {
  int a = -1;
  if (v.is_string()) {
    const std::string s = v.get<std::string>();
    if (s == "x") a = 0;
    else if (s == "y") a = 1;
    else if (s == "z") a = 2;
  } else if (v.is_number_integer()) {
    a = v.get<int>();
  }
  if (a < 0 || a >= dim)
    throw InputError(ptr, std::string("expected an axis: \"x\", \"y\"") + (dim == 3 ? ", \"z\"" : "") + " or 0.." +
                              std::to_string(dim - 1) + ", got " + v.dump());
  return a;
}

Bins Bins::parse(const Params& p, const std::string& key, int dim, const std::vector<std::string>& extra) {
  Bins b;
  if (!p.has(key)) return b;
  const nlohmann::json& o = p.raw(key);
  b.pointer = p.pointer(key);
  if (!o.is_object()) throw InputError(b.pointer, "expected an object {\"axis\", \"bins\", \"range\"}, got " + o.dump());
  for (auto it = o.begin(); it != o.end(); ++it) {
    bool known = it.key() == "axis" || it.key() == "bins" || it.key() == "range";
    for (const auto& e : extra) known = known || it.key() == e;
    if (!known) throw InputError(b.pointer + "/" + it.key(), "unknown key \"" + it.key() + "\"");
  }
  b.on = true;
  if (!o.contains("axis")) throw InputError(b.pointer + "/axis", "missing \"axis\": the direction of the bins");
  b.axis = axis_of(o["axis"], dim, b.pointer + "/axis");
  if (o.contains("bins")) {
    if (!o["bins"].is_number_integer() || o["bins"].get<int>() < 1 || o["bins"].get<int>() > 100000)
      throw InputError(b.pointer + "/bins", "expected a number of bins (an integer from 1), got " + o["bins"].dump());
    b.count = o["bins"].get<int>();
  }
  if (o.contains("range")) {
    const auto& r = o["range"];
    if (!r.is_array() || r.size() != 2 || !r[0].is_number() || !r[1].is_number() || !(r[0].get<double>() < r[1].get<double>()))
      throw InputError(b.pointer + "/range", "expected [from, to] with from < to (m, along the axis), got " + r.dump());
    b.fixed_range = true;
    b.from = r[0].get<double>();
    b.to = r[1].get<double>();
  }
  return b;
}

void Bins::edges(const double lo[3], const double hi[3], double& a, double& b) const {
  a = fixed_range ? from : lo[axis];
  b = fixed_range ? to : hi[axis];
}

int Bins::bin(double x, double a, double b) const {
  if (!(x >= a) || !(x < b)) return x == b ? count - 1 : -1;
  const int k = static_cast<int>((x - a) / (b - a) * count);
  return k < count ? k : count - 1;
}

std::vector<double> bin_centres(int n, double a, double b) {
  std::vector<double> c(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) c[static_cast<std::size_t>(i)] = a + (i + 0.5) * (b - a) / n;
  return c;
}

std::vector<char> contacts_in(const AnalysisFrame& f, const Region& r) {
  const int d = f.dimension;
  std::vector<char> in(f.contacts.count, 0);
  for (std::size_t c = 0; c < f.contacts.count; ++c) in[c] = r.contains(&f.contacts.point[c * d], d) ? 1 : 0;
  return in;
}

void profile_param(Schema& s, const std::string& doc) {
  s.object("profile", doc + ": {\"axis\": \"x\"|\"y\"|\"z\", \"bins\": n (default 10), \"range\": [from, to] (m; "
                            "default: the region's box in each frame)}")
      .optional();
}

}  // namespace moreau::analysis
