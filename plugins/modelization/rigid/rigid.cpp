// `rigid`: rigid bodies in 2D and 3D. A body is one node of the set `rigid.nodes`, with
// k = 3 (2D: vx vy ω) or 6 (3D: v, ω) unknowns. Declares the rigid field table and fills
// each body's row from the scene: pose, velocities, mass and inertia (explicit, or from
// the contactors' geometry and the material density). Gravity and the gyroscopic term are
// the integrator's, so the bulk stage has nothing to do. For the contact side: the
// velocity of a material point, v + ω × r, in the contact frame (the rows of H).
//
// The state's position is the centre of mass. When the inertia comes from the contactors
// (a cluster placed freely in the scene's body frame), the body origin moves to their
// centre of mass c: position x + R c, velocity v + ω × R c (the same rigid motion), and
// init_body returns c so that the kernel re-expresses the placements about it. The
// inertia tensor stays in the scene's body axes, full (the integrator takes all six
// components), so no principal-axes rotation is needed.
#include <array>
#include <cmath>
#include <moreau/field_cache.hpp>
#include <moreau/modelization.hpp>
#include <moreau/rigid_fields.hpp>

namespace {

using namespace moreau;
namespace R = moreau::rigid;

class Rigid : public Modelization {
 public:
  static Schema schema() { return {}; }
  static constexpr const char* doc = "rigid bodies (Newton-Euler), 2D and 3D";
  Rigid(const Params&, const BuildContext&) {}

  std::string node_set() const override { return R::nodes; }
  int node_dofs(int dim) const override { return dim == 2 ? 3 : 6; }
  std::vector<FieldSpec> fields(int) const override { return R::fields(); }
  std::string default_integrator() const override { return "theta"; }

  Schema body_schema(int dim) const override {
    Schema s;
    s.boolean("fixed", "the body never moves").fallback(false);
    s.vector("position", "position of the body origin", length::dimension).units("m");
    if (dim == 2) {
      s.number("angle", "rotation angle").units("rad").fallback(0.0);
      s.number("angular_velocity", "angular velocity").units("rad/s").fallback(0.0);
      s.number("inertia", "polar moment of inertia about the origin (per unit thickness)").units("kg m2").gt(0).optional();
    } else {
      s.vector("orientation", "unit quaternion w x y z", length::orientation).fallback({1.0, 0.0, 0.0, 0.0});
      s.vector("angular_velocity", "angular velocity, world frame", length::rotation).units("rad/s")
          .fallback({0.0, 0.0, 0.0});
      s.vector("inertia", "inertia about the origin, body frame: 3 principal moments, or xx yy zz xy xz yz",
               length::any).units("kg m2").optional();
    }
    s.vector("velocity", "velocity of the body origin", length::dimension).units("m/s").optional();
    s.string("material", "material name (its density gives mass and inertia from the contactors)").optional();
    s.number("mass", "mass (2D: per unit thickness); overrides the material").units("kg").gt(0).optional();
    return s;
  }

  std::array<double, 3> init_body(State& st, std::size_t body, const Params& p,
                                  const std::optional<MassProperties>& shapes, const Params* material) override {
    resolved(contact_fields_, st);
    const int d = st.dimension();
    const std::size_t b = st.body(body).first_node;  // its row in rigid.nodes
    const bool fixed = p.boolean("fixed");
    st.field(R::nodes, R::fixed).row(b)[0] = fixed ? 1.0 : 0.0;
    set_both(st.field(R::nodes, R::position), b, p.vector("position"));
    const std::vector<double> v = p.has("velocity") ? p.vector("velocity") : std::vector<double>(d, 0.0);
    set_both(st.field(R::nodes, R::velocity), b, fixed ? std::vector<double>(d, 0.0) : v);
    if (d == 2) {
      set_both(st.field(R::nodes, R::angle), b, {p.number("angle")});
      set_both(st.field(R::nodes, R::angular_velocity), b, {fixed ? 0.0 : p.number("angular_velocity")});
    } else {
      std::vector<double> q = p.vector("orientation");
      const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
      if (std::fabs(n - 1) > 1e-6)
        throw p.error("orientation", "expected a unit quaternion [w, x, y, z], its norm is " + std::to_string(n));
      for (double& x : q) x /= n;
      set_both(st.field(R::nodes, R::orientation), b, q);
      set_both(st.field(R::nodes, R::angular_velocity), b, fixed ? std::vector<double>(3, 0.0) : p.vector("angular_velocity"));
    }

    // The origin moves to the contactors' centre of mass when the inertia comes from them.
    // Not for a fixed body (it never moves: floors, slopes, half-spaces without a centre),
    // nor with an explicit inertia (the scene then says the origin is the centre of mass).
    // Below 1e-9 of the body's size the centre is a rounding error of computed centroids:
    // the origin stays, so symmetric bodies keep exactly the position the scene gives.
    std::array<double, 3> origin{0, 0, 0};
    const double size = shapes ? std::pow(std::fabs(shapes->volume), 1.0 / d) : 0.0;
    if (shapes && !fixed && !p.has("inertia") && shapes->volume > 0 &&
        std::hypot(shapes->center[0], shapes->center[1], d == 3 ? shapes->center[2] : 0.0) > 1e-9 * size) {
      origin = {shapes->center[0], shapes->center[1], d == 3 ? shapes->center[2] : 0.0};
      move_origin(st, b, origin);
    }

    // Mass: explicit, or density × volume of the contactors.
    double mass = 0;
    if (p.has("mass")) mass = p.number("mass");
    else if (shapes && material) mass = material->number("density") * shapes->volume;
    if (!fixed && !(mass > 0))
      throw p.error("", "a body that is not fixed needs a mass: give \"mass\" and \"inertia\", or contactors and a "
                        "\"material\" with a density");
    st.field(R::nodes, R::mass).row(b)[0] = mass;
    st.field(R::nodes, R::inverse_mass).row(b)[0] = fixed ? 0.0 : 1.0 / mass;

    // Inertia: explicit, or the contactors' unit-density inertia scaled to the mass.
    std::vector<double> I(d == 2 ? 1 : 6, 0.0);
    if (p.has("inertia")) {
      if (d == 2) I[0] = p.number("inertia");
      else {
        auto in = p.vector("inertia");
        if (in.size() == 3) I = {in[0], in[1], in[2], 0, 0, 0};
        else if (in.size() == 6) I = in;
        else throw p.error("inertia", "expected 3 principal moments or 6 components (xx yy zz xy xz yz), got " +
                                          std::to_string(in.size()) + " numbers");
      }
    } else if (shapes && shapes->volume > 0) {
      const double scale = mass / shapes->volume;  // = density when the mass came from it
      const auto& J = shapes->inertia;
      if (d == 2) I[0] = scale * J[8];
      else I = {scale * J[0], scale * J[4], scale * J[8], scale * J[1], scale * J[2], scale * J[5]};
    } else if (!fixed) {
      throw p.error("", "a body with an explicit mass and no contactors needs \"inertia\"");
    }
    st.field(R::nodes, R::inertia).row(b).data()[0] = I[0];
    for (std::size_t k = 0; k < I.size(); ++k) st.field(R::nodes, R::inertia).row(b)[k] = I[k];
    auto inv = st.field(R::nodes, R::inverse_inertia).row(b);
    if (fixed) {
      for (double& x : inv) x = 0;
    } else if (d == 2) {
      if (!(I[0] > 0)) throw p.error("inertia", "the moment of inertia must be positive");
      inv[0] = 1 / I[0];
    } else {
      invert_symmetric(I, inv, p);
    }
    return origin;
  }

  void bulk(StepContext&) override {}
  bool has_bulk() const override { return false; }

  void generalised_velocity(const State& st, Velocity which, std::size_t n, double* out) const override {
    const int d = st.dimension(), nr = d == 2 ? 1 : 3;
    const bool begin = which == Velocity::begin;
    ContactFields other;
    const ContactFields& f = resolved(contact_fields_, st, other);
    const double* v = (begin ? f.velocity : f.free_velocity)->data(Depth::begin);
    const double* w = (begin ? f.angular_velocity : f.free_angular_velocity)->data(Depth::begin);
    for (int k = 0; k < d; ++k) out[k] = v[n * d + k];
    for (int k = 0; k < nr; ++k) out[d + k] = w[n * nr + k];
  }

  /// Rows of the local frame applied to [I, −[r]×] (3D) or [I, (−r_y, r_x)ᵀ] (2D), with r
  /// the lever arm from the centre of mass at the detection configuration.
  void contact_jacobian(const State& st, const PointOnBody& p, double* H) const override {
    const int d = st.dimension();
    ContactFields other;
    const Field* at = resolved(contact_fields_, st, other).detection_position;
    const double* c = (at ? *at : st.field(R::nodes, R::detection_position)).data() + p.nodes[0] * d;  // (throws without it, as before)
    const double r[3] = {p.point[0] - c[0], p.point[1] - c[1], d == 3 ? p.point[2] - c[2] : p.point[2] - 0.0};
    const double* e0 = p.frame;
    if (d == 2) {
      for (int i = 0; i < 2; ++i) {
        const double* e = e0 + 2 * i;
        H[i * 3 + 0] = e[0];
        H[i * 3 + 1] = e[1];
        H[i * 3 + 2] = -e[0] * r[1] + e[1] * r[0];  // e · (ω ẑ × r)
      }
      return;
    }
    for (int i = 0; i < 3; ++i) {
      const double* e = e0 + 3 * i;
      H[i * 6 + 0] = e[0];
      H[i * 6 + 1] = e[1];
      H[i * 6 + 2] = e[2];
      // e · (ω × r) = ω · (r × e)
      H[i * 6 + 3] = r[1] * e[2] - r[2] * e[1];
      H[i * 6 + 4] = r[2] * e[0] - r[0] * e[2];
      H[i * 6 + 5] = r[0] * e[1] - r[1] * e[0];
    }
  }

 private:
  /// The fields the contact side reads for every contact side and node (contact_jacobian,
  /// generalised_velocity), resolved once (init_body; moreau/field_cache.hpp) instead of
  /// looked up by name at each call: two lookups a call were about a sixth of a 10⁴-sphere
  /// step's assembly. A State this modelization has not filled (none in a run) is looked up.
  struct ContactFields {
    FieldCacheKey cache_key;
    const Field *detection_position = nullptr, *velocity = nullptr, *angular_velocity = nullptr, *free_velocity = nullptr,
                *free_angular_velocity = nullptr;
    /// By name (throws, naming the field, when one is missing: as the lookups at each call did).
    static ContactFields of(const State& st) {
      const EntitySet& s = st.set(R::nodes);
      ContactFields f;
      f.detection_position = s.find(R::detection_position);  // only with interactions (Needed::contacts)
      f.velocity = &s.field(R::velocity);
      f.angular_velocity = &s.field(R::angular_velocity);
      f.free_velocity = &s.field(R::free_velocity);
      f.free_angular_velocity = &s.field(R::free_angular_velocity);
      f.cache_key.take(st, s);
      return f;
    }
  };
  ContactFields contact_fields_;

  /// Moves the body origin to the body-frame point c (both depths): x += R c, v += ω × R c.
  static void move_origin(State& st, std::size_t b, const std::array<double, 3>& c) {
    const int d = st.dimension();
    double r[3] = {0, 0, 0}, wxr[3] = {0, 0, 0};
    if (d == 2) {
      const double a = st.field(R::nodes, R::angle).row(b)[0], w = st.field(R::nodes, R::angular_velocity).row(b)[0];
      r[0] = std::cos(a) * c[0] - std::sin(a) * c[1];
      r[1] = std::sin(a) * c[0] + std::cos(a) * c[1];
      wxr[0] = -w * r[1];
      wxr[1] = w * r[0];
    } else {
      const auto q = st.field(R::nodes, R::orientation).row(b);
      const auto w = st.field(R::nodes, R::angular_velocity).row(b);
      // r = q c q*: t = 2 u × c, r = c + w t + u × t (u the vector part).
      const double u[3] = {q[1], q[2], q[3]};
      const double t[3] = {2 * (u[1] * c[2] - u[2] * c[1]), 2 * (u[2] * c[0] - u[0] * c[2]), 2 * (u[0] * c[1] - u[1] * c[0])};
      r[0] = c[0] + q[0] * t[0] + u[1] * t[2] - u[2] * t[1];
      r[1] = c[1] + q[0] * t[1] + u[2] * t[0] - u[0] * t[2];
      r[2] = c[2] + q[0] * t[2] + u[0] * t[1] - u[1] * t[0];
      wxr[0] = w[1] * r[2] - w[2] * r[1];
      wxr[1] = w[2] * r[0] - w[0] * r[2];
      wxr[2] = w[0] * r[1] - w[1] * r[0];
    }
    for (Depth dp : {Depth::begin, Depth::end}) {
      auto x = st.field(R::nodes, R::position).row(b, dp);
      auto v = st.field(R::nodes, R::velocity).row(b, dp);
      for (int k = 0; k < d; ++k) {
        x[k] += r[k];
        v[k] += wxr[k];
      }
    }
  }

  static void set_both(Field& f, std::size_t b, const std::vector<double>& v) {
    for (Depth dp : {Depth::begin, Depth::end}) {
      auto row = f.row(b, dp);
      for (std::size_t k = 0; k < row.size(); ++k) row[k] = v[k];
    }
  }

  /// Inverse of the symmetric tensor (xx yy zz xy xz yz); it must be positive definite.
  static void invert_symmetric(const std::vector<double>& I, std::span<double> out, const Params& p) {
    const double a = I[0], e = I[1], i = I[2], b = I[3], c = I[4], f = I[5];
    // Cofactors of [[a b c][b e f][c f i]].
    const double A = e * i - f * f, B = c * f - b * i, C = b * f - c * e;
    const double E = a * i - c * c, F = b * c - a * f, Ii = a * e - b * b;
    const double det = a * A + b * B + c * C;
    if (!(a > 0) || !(Ii > 0) || !(det > 0))
      throw p.error("inertia", "the inertia tensor must be positive definite");
    out[0] = A / det;
    out[1] = E / det;
    out[2] = Ii / det;
    out[3] = B / det;
    out[4] = C / det;
    out[5] = F / det;
  }
};

MOREAU_REGISTER(Rigid, "rigid")

}  // namespace

MOREAU_PLUGIN_LIBRARY("moreau_modelization_rigid")
