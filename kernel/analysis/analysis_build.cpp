#include "analysis_build.hpp"

#include <cmath>
#include <moreau/node_fields.hpp>
#include <set>
#include <sstream>

#include "../contact/placement.hpp"
#include "../plugin/registry.hpp"
#include "../run/world.hpp"
#include "frame_view.hpp"

namespace moreau::kernel {

using nlohmann::json;

namespace {

std::string point_text(const std::array<double, 3>& p, int d) {
  std::ostringstream s;
  s.precision(6);
  s << "[";
  for (int k = 0; k < d; ++k) s << (k ? ", " : "") << p[k];
  s << "]";
  return s.str();
}

/// `region`: "all", or {"min": [d numbers], "max": [d numbers]} with min < max.
bool parse_region(const json& r, int d, const std::string& ptr, Region& out, std::vector<InputError>* errors) {
  auto fail = [&](const std::string& where, const std::string& msg) {
    if (errors) errors->emplace_back(where, msg);
    return false;
  };
  out = Region{};
  if (r.is_string()) {
    if (r == "all") return true;
    return fail(ptr, "expected \"all\" (the whole sample) or a box {\"min\": [...], \"max\": [...]}, got " + r.dump());
  }
  if (!r.is_object()) return fail(ptr, "expected \"all\" or a box {\"min\": [...], \"max\": [...]}, got " + r.dump());
  for (auto it = r.begin(); it != r.end(); ++it)
    if (it.key() != "min" && it.key() != "max")
      return fail(ptr + "/" + it.key(), "unknown key \"" + it.key() + "\": a region box has \"min\" and \"max\"");
  out.whole = false;
  for (const char* key : {"min", "max"}) {
    if (!r.contains(key)) return fail(ptr + "/" + key, std::string("missing \"") + key + "\": the box's corner");
    const json& v = r[key];
    if (!v.is_array() || v.size() != static_cast<std::size_t>(d))
      return fail(ptr + "/" + key, "expected " + std::to_string(d) + " numbers, got " + v.dump());
    for (int k = 0; k < d; ++k) {
      if (!v[k].is_number()) return fail(ptr + "/" + key + "/" + std::to_string(k), "expected a number, got " + v[k].dump());
      (key[1] == 'i' ? out.lo : out.hi)[k] = v[k].get<double>();
    }
  }
  for (int k = 0; k < d; ++k)
    if (!(out.lo[k] < out.hi[k]))
      return fail(ptr + "/max/" + std::to_string(k), "the box is empty: max " + point_text(out.hi, d) +
                                                         " must exceed min " + point_text(out.lo, d) + " in every component");
  return true;
}

/// The box around the scene at the start: every node's position and the bounds of bounded
/// shapes, each at its node's pose.
void scene_extent(const World& w, std::array<double, 3>& lo, std::array<double, 3>& hi) {
  const State& st = w.state;
  const int d = st.dimension();
  bool any = false;
  auto grow = [&](const double* a, const double* b) {
    for (int k = 0; k < d; ++k) {
      lo[k] = any ? std::min(lo[k], a[k]) : a[k];
      hi[k] = any ? std::max(hi[k], b[k]) : b[k];
    }
    any = true;
  };
  for (const auto& m : st.models()) {
    if (!st.has(m.nodes, node_fields::position)) continue;
    const Field& x = st.field(m.nodes, node_fields::position);
    for (std::size_t i = 0; i < x.rows(); ++i) grow(x.row(i, Depth::begin).data(), x.row(i, Depth::begin).data());
  }
  if (!w.contacts) return;
  for (const auto& c : w.contacts->contactors) {
    const std::string& set = st.models()[static_cast<std::size_t>(c.model)].nodes;
    if (!st.has(set, node_fields::position)) continue;
    double node[7] = {0, 0, 0, 0, 0, 0, 0};
    if (d == 3) node[3] = 1;
    const auto x = st.field(set, node_fields::position).row(c.node, Depth::begin);
    for (int k = 0; k < d; ++k) node[k] = x[k];
    const char* rot = d == 2 ? node_fields::angle : node_fields::orientation;
    if (st.has(set, rot)) {
      const auto q = st.field(set, rot).row(c.node, Depth::begin);
      for (std::size_t k = 0; k < q.size(); ++k) node[3 + k] = q[k];
    }
    double pose[7], a[3], b[3];
    compose_pose(d, node, c.placement, pose);
    c.shape->bounds(d, Pose{pose, pose + 3}, a, b);
    for (int k = 0; k < d; ++k) {  // an unbounded direction (a half-space) adds nothing
      if (!std::isfinite(a[k])) a[k] = lo[k];
      if (!std::isfinite(b[k])) b[k] = hi[k];
    }
    grow(a, b);
  }
}

}  // namespace

std::vector<std::string> analysis_kernel_keys() { return {"name", "region", "every"}; }

void check_analysis_entries(const std::vector<AnalysisEntry>& entries, int dim, std::vector<InputError>& errors) {
  std::set<std::string> names;
  for (const auto& e : entries) {
    const json& j = e.entry;
    if (!j.is_object()) continue;  // reported by the plugin check
    std::string name = e.type;
    if (j.contains("name")) {
      if (!j["name"].is_string() || j["name"].get<std::string>().empty() ||
          j["name"].get<std::string>().find('/') != std::string::npos) {
        errors.emplace_back(e.pointer + "/name", "expected a name (a non-empty string without '/'), got " + j["name"].dump());
        continue;
      }
      name = j["name"].get<std::string>();
    }
    if (!names.insert(name).second)
      errors.emplace_back(e.pointer + (j.contains("name") ? "/name" : ""),
                          "two analyses named \"" + name + "\": give each its own \"name\" (its group in the frames)");
    if (j.contains("every") && (!j["every"].is_number_integer() || j["every"].get<long>() < 1))
      errors.emplace_back(e.pointer + "/every", "expected an integer >= 1 (every N-th output frame), got " + j["every"].dump());
    if (j.contains("region")) {
      Region r;
      parse_region(j["region"], dim, e.pointer + "/region", r, &errors);
    }
  }
}

std::unique_ptr<AnalysisRunner> build_analyses(const World& w, Registry& reg, const BuildContext& ctx,
                                               const std::vector<AnalysisEntry>& entries) {
  const int d = w.dimension;
  std::array<double, 3> lo{0, 0, 0}, hi{0, 0, 0};
  scene_extent(w, lo, hi);
  FrameView view(w);
  std::vector<AnalysisUse> uses;
  for (const auto& e : entries) {
    AnalysisUse u;
    u.type = e.type;
    u.name = e.entry.value("name", e.type);
    u.pointer = e.pointer;
    u.every = e.entry.value("every", 1L);
    if (e.entry.contains("region")) parse_region(e.entry["region"], d, e.pointer + "/region", u.region, nullptr);
    if (!u.region.whole) {
      for (int k = 0; k < d; ++k)
        if (u.region.hi[k] < lo[k] || u.region.lo[k] > hi[k])
          throw InputError(e.pointer + "/region", "the box " + point_text(u.region.lo, d) + " to " +
                                                      point_text(u.region.hi, d) +
                                                      " lies outside the scene, whose bodies and shapes span " +
                                                      point_text(lo, d) + " to " + point_text(hi, d) + " at the start");
    }
    u.analysis = reg.create<Analysis>(e.type, e.params, ctx, e.pointer);
    AnalysisSetup setup;
    setup.dimension = d;
    setup.body_names = w.state.names();
    setup.groups = view.all_groups();
    setup.group_names = view.group_names();
    if (w.scene.contains("interactions"))
      for (const auto& in : w.scene["interactions"])
        setup.interactions.push_back({in["groups"][0].get<std::string>(), in["groups"][1].get<std::string>()});
    setup.region = u.region;
    setup.pointer = e.pointer;
    setup.region_pointer = e.pointer + "/region";
    u.analysis->prepare(setup);
    uses.push_back(std::move(u));
  }
  return std::make_unique<AnalysisRunner>(w, std::move(uses));
}

}  // namespace moreau::kernel
