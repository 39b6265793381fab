// `walls`: the loads on chosen bodies (silo walls, a floor, a piston): the resultant force
// and torque (about the body's centre) of their contacts, and — with `profile` — each
// wall's stresses in bins along an axis: normal stress Σ f_n / (Δ·width), shear stress
// Σ (force on the wall · axis) / (Δ·width), the mean mobilisation ‖r_t‖/(μ r_n) and the
// share of contacts on the Coulomb cone's boundary. `surface` is the top of the sample
// along the axis (highest centre + bounding radius), to measure depths from.
// With `average`, the resultants are also averaged over every step since the last frame
// written (a piston's load in a flow, impacts included).
#include <analysis_tools.hpp>
#include <cmath>
#include <moreau/analysis.hpp>
#include <moreau/error.hpp>

namespace {

using namespace moreau;
using namespace moreau::analysis;

class Walls : public Analysis {
 public:
  static Schema schema() {
    Schema s;
    s.array("bodies", "names of the bodies whose loads are reported (e.g. the silo's walls)");
    profile_param(s, "wall stresses in bins along an axis; 3D also needs \"width\", the wall's extent across the "
                     "axis (m, e.g. a cylinder's perimeter)");
    s.number("cone_tolerance", "a contact is on the cone's boundary when |r_t| >= (1 - tol) mu r_n").min(0).lt(1).fallback(1e-3);
    s.boolean("average", "also the force and torque averaged over every step since the frame this analysis last wrote "
                         "(impacts between frames included): datasets average/...")
        .fallback(false);
    return s;
  }
  static constexpr const char* doc = "force and torque on chosen bodies, wall normal and shear stress profile along an axis";

  Walls(const Params& p, const BuildContext& ctx)
      : dim_(ctx.dimension), tol_(p.number("cone_tolerance")), average_(p.boolean("average")) {
    names_json_ = p.raw("bodies");
    names_pointer_ = p.pointer("bodies");
    bins_ = Bins::parse(p, "profile", dim_, {"width"});
    if (bins_.on) {
      const auto& o = p.raw("profile");
      if (o.contains("width")) {
        if (!o["width"].is_number() || !(o["width"].get<double>() > 0))
          throw InputError(bins_.pointer + "/width", "expected the wall's width across the axis (m, > 0), got " + o["width"].dump());
        width_ = o["width"].get<double>();
      } else if (dim_ == 3) {
        throw InputError(bins_.pointer + "/width", "missing \"width\": in 3D the stress needs the wall's extent across the axis (m)");
      }
    }
  }

  void prepare(const AnalysisSetup& s) override {
    if (!names_json_.is_array() || names_json_.empty())
      throw InputError(names_pointer_, "expected a non-empty list of body names");
    for (std::size_t i = 0; i < names_json_.size(); ++i) {
      const std::string ptr = names_pointer_ + "/" + std::to_string(i);
      if (!names_json_[i].is_string()) throw InputError(ptr, "expected a body name, got " + names_json_[i].dump());
      const std::string name = names_json_[i].get<std::string>();
      int found = -1;
      for (std::size_t b = 0; b < s.body_names.size(); ++b)
        if (s.body_names[b] == name) found = static_cast<int>(b);
      if (found < 0) throw InputError(ptr, "no body named \"" + name + "\"");
      names_.push_back(name);
      index_.push_back(found);
    }
  }

  bool every_step() const override { return average_; }

  void step(const AnalysisFrame& f, const Region& region) override {
    const Loads l = loads(f, region, false);
    sum_force_.resize(l.force.size(), 0.0);
    sum_torque_.resize(l.torque.size(), 0.0);
    for (std::size_t i = 0; i < l.force.size(); ++i) sum_force_[i] += l.force[i] * f.h;
    for (std::size_t i = 0; i < l.torque.size(); ++i) sum_torque_[i] += l.torque[i] * f.h;
    summed_time_ += f.h;
    ++summed_steps_;
  }

  void run(const AnalysisFrame& f, const Region& region, AnalysisResult& out) override {
    const int d = f.dimension, r = d == 2 ? 1 : 3;
    const std::size_t nw = index_.size(), ds = static_cast<std::size_t>(d), rs = static_cast<std::size_t>(r);
    const Loads l = loads(f, region, bins_.on);
    out.strings("bodies", names_);
    out.add("force", {nw, ds}, l.force, d == 2 ? "N/m" : "N");
    out.add("torque", {nw, rs}, l.torque, d == 2 ? "N" : "N m");
    out.add("contacts", {nw}, l.count);
    if (average_) {
      const double T = summed_time_;
      std::vector<double> mf(nw * ds, NAN), mt(nw * rs, NAN);
      for (std::size_t i = 0; T > 0 && i < mf.size(); ++i) mf[i] = sum_force_[i] / T;
      for (std::size_t i = 0; T > 0 && i < mt.size(); ++i) mt[i] = sum_torque_[i] / T;
      out.add("average/force", {nw, ds}, mf, d == 2 ? "N/m" : "N");
      out.add("average/torque", {nw, rs}, mt, d == 2 ? "N" : "N m");
      out.scalar("average/duration", T, "s");
      out.scalar("average/steps", static_cast<double>(summed_steps_));
      sum_force_.clear();
      sum_torque_.clear();
      summed_time_ = 0;
      summed_steps_ = 0;
    }
    if (!bins_.on) return;
    const std::size_t nbins = static_cast<std::size_t>(bins_.count);
    // The top of the sample along the axis: depths are measured from it.
    double top = -INFINITY;
    for (std::size_t i = 0; i < f.bodies.count; ++i)
      if (f.bodies.sample[i] && std::isfinite(f.bodies.radius[i]))
        top = std::max(top, f.bodies.position[i * d + bins_.axis] + f.bodies.radius[i]);
    out.scalar("profile/axis", bins_.axis);
    out.scalar("profile/surface", std::isfinite(top) ? top : 0.0, "m");
    out.add("profile/position", {nbins}, bin_centres(bins_.count, l.a, l.b), "m");
    out.add("profile/normal", {nw, nbins}, l.normal, "Pa");
    out.add("profile/shear", {nw, nbins}, l.shear, "Pa");
    out.add("profile/mobilisation", {nw, nbins}, l.mob);
    out.add("profile/sliding_share", {nw, nbins}, l.cone);
    out.add("profile/contacts", {nw, nbins}, l.nbin);
  }

 private:
  /// Per wall: resultant force [nw×d], torque [nw×r] and contacts [nw]; with `profile`, per
  /// wall and bin [nw×n]: the stresses, mean mobilisation and share on the cone.
  struct Loads {
    std::vector<double> force, torque, count, normal, shear, mob, cone, nbin;
    double a = 0, b = 0;
  };

  Loads loads(const AnalysisFrame& f, const Region& region, bool profile) const {
    const int d = f.dimension, r = d == 2 ? 1 : 3;
    const std::size_t nw = index_.size();
    std::vector<int> wall_of(f.bodies.count, -1);
    for (std::size_t w = 0; w < nw; ++w) wall_of[static_cast<std::size_t>(index_[w])] = static_cast<int>(w);
    Loads l;
    std::vector<double>&force = l.force, &torque = l.torque, &count = l.count;
    force.assign(nw * d, 0.0);
    torque.assign(nw * r, 0.0);
    count.assign(nw, 0.0);
    const auto in = contacts_in(f, region);
    double lo[3], hi[3];
    region_box(f, region, lo, hi);
    double &a = l.a, &b = l.b;
    if (profile) bins_.edges(lo, hi, a, b);
    const std::size_t nbins = profile ? static_cast<std::size_t>(bins_.count) : 0;
    // Per wall and bin.
    const std::size_t nwb = nw * nbins;
    for (auto* v : {&l.normal, &l.shear, &l.mob, &l.cone, &l.nbin}) v->assign(nwb, 0.0);
    std::vector<double>&normal = l.normal, &shear = l.shear, &mob = l.mob, &cone = l.cone, &nbin = l.nbin;
    for (std::size_t c = 0; c < f.contacts.count; ++c) {
      if (!in[c]) continue;
      for (int s = 0; s < 2; ++s) {
        const int w = wall_of[static_cast<std::size_t>(f.contacts.bodies[2 * c + s])];
        if (w < 0) continue;
        double fc[3];
        contact_force(f, c, fc);
        const double sign = s == 0 ? 1.0 : -1.0;  // the force on this side
        const std::size_t body = static_cast<std::size_t>(index_[static_cast<std::size_t>(w)]);
        double arm[3] = {0, 0, 0};
        for (int k = 0; k < d; ++k) {
          force[static_cast<std::size_t>(w) * d + k] += sign * fc[k];
          arm[k] = f.contacts.point[c * d + k] - f.bodies.position[body * d + k];
        }
        if (d == 2) {
          torque[static_cast<std::size_t>(w)] += sign * (arm[0] * fc[1] - arm[1] * fc[0]);
        } else {
          torque[w * 3 + 0] += sign * (arm[1] * fc[2] - arm[2] * fc[1]);
          torque[w * 3 + 1] += sign * (arm[2] * fc[0] - arm[0] * fc[2]);
          torque[w * 3 + 2] += sign * (arm[0] * fc[1] - arm[1] * fc[0]);
        }
        count[static_cast<std::size_t>(w)] += 1;
        if (!profile) continue;
        const int k = bins_.bin(f.contacts.point[c * d + bins_.axis], a, b);
        if (k < 0) continue;
        const std::size_t kk = static_cast<std::size_t>(w) * nbins + static_cast<std::size_t>(k);
        const double area = (b - a) / bins_.count * width_;
        normal[kk] += f.contacts.impulse[c * d] / f.h / area;
        shear[kk] += sign * fc[bins_.axis] / area;
        if (f.contacts.impulse[c * d] > 0) {
          const double m = mobilisation(f, c);
          mob[kk] += m;
          if (m >= 1 - tol_) cone[kk] += 1;
          nbin[kk] += 1;
        }
      }
    }
    for (std::size_t k = 0; k < nwb; ++k)
      if (nbin[k] > 0) mob[k] /= nbin[k], cone[k] /= nbin[k];
    return l;
  }

  int dim_;
  double tol_;
  bool average_ = false;
  std::vector<double> sum_force_, sum_torque_;  // force·h, torque·h per wall since the last frame written (average)
  double summed_time_ = 0;
  long summed_steps_ = 0;
  double width_ = 1;  // 2D: per unit thickness
  nlohmann::json names_json_;
  std::string names_pointer_;
  std::vector<std::string> names_;
  std::vector<int> index_;
  Bins bins_;
};

MOREAU_REGISTER(Walls, "walls")

}  // namespace

MOREAU_PLUGIN_LIBRARY("moreau_analysis_walls")
