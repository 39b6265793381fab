// `theta`: the θ-method of Moreau–Jean for rigid bodies (DESIGN §1).
//
//   v_free = v⁻ + h M⁻¹ F̄            (F̄: gravity and external forces at the θ-point)
//   v⁺     = v_free + M⁻¹ p          (p: contact impulse of the step, if any)
//   x⁺     = x⁻ + h [(1−θ) v⁻ + θ v⁺]
//
// Rotations (3D) are integrated on SO(3): with Ω the body-frame angular velocity,
// I(Ω⁺ − Ω⁻) = h[−Ω×IΩ + Rᵀτ]_θ is solved linearly implicitly (one Newton step from Ω⁻,
// which keeps the θ = 0.5 scheme second order), and q⁺ = q⁻ ⊗ exp(h Ω_θ / 2) with
// Ω_θ = (1−θ)Ω⁻ + θΩ⁺ (computed in world axes as exp(φ/2) ⊗ q⁻), so quaternions stay unit. Bodies with isotropic inertia skip the
// gyroscopic solve (Ω×IΩ = 0). Contact impulses act with the world inverse inertia at
// the start of the step, R⁻ I⁻¹ R⁻ᵀ, which is what compact_inverse() reports. Every field
// is a node field of `rigid.nodes` (a rigid body is one node).
#include <cmath>
#include <stdexcept>
#include <moreau/field_cache.hpp>
#include <moreau/integrator.hpp>
#include <moreau/rigid_fields.hpp>

#include "rotation.hpp"

namespace {

using namespace moreau;
namespace R = moreau::rigid;
using namespace moreau::theta;

/// Raw pointers to the fields of one step (the hot loops index them directly).
struct Fields {
  double *x0, *x1, *v0, *v1, *w0, *w1, *q0, *q1;  // begin / end depths (q: angle in 2D)
  double *vf, *wf, *im, *ii, *I, *F, *T, *P, *imp;  // P: reaction, k per node (linear, then angular)
  std::size_t n;  // nodes (rigid bodies)
};

class Theta : public Integrator {
 public:
  static Schema schema() { return {}; }
  static constexpr const char* doc = "theta-method (Moreau-Jean) for rigid bodies; theta from time.theta";
  Theta(const Params&, const BuildContext&) {}

  void prepare(State& st, const Modelization& model) override {
    for (const char* f : {R::position, R::velocity, R::angular_velocity, R::inverse_mass, R::inverse_inertia})
      if (!st.has(R::nodes, f))
        throw InputError("/time/integrator", "the theta integrator works on rigid bodies: modelization \"" +
                                                 model.node_set() + "\" has no rigid field '" + f + "'");
    resolved(inverse_fields_, st);  // checked again at each detection; the node fields: at the first step
  }

  void free_velocity(StepContext& c) override {
    Fields f = fields(c.state, c.external_forces, false);
    if (c.state.dimension() == 2) free_2d(c, f);
    else free_3d(c, f);
  }

  void update_dofs(StepContext& c) override {
    Fields f = fields(c.state, c.external_forces, c.contact_impulses);
    if (c.state.dimension() == 2) update_2d(c, f);
    else update_3d(c, f);
  }

  void detection_configuration(StepContext& c) override {
    // Contacts are detected on the predicted configuration q_θ = q⁻ + (1−θ) h v⁻ (LMGC90's
    // choice): the θ-scheme moves bodies from there by θ h v⁺, so a constraint on v⁺ with
    // the gap at q_θ keeps contacts from closing further during the step.
    State& st = c.state;
    const int d = st.dimension();
    const NodeFields& r = resolved(node_fields_, st);
    resolved(inverse_fields_, st);  // a field declared since: compact_inverse() (const) would look up at each call
    if (!r.px || !r.pq || !r.travel) throw std::logic_error("theta: the node set has no detection fields");
    const std::size_t nb = r.nodes->rows();
    const double a = (1 - c.theta) * c.h;
    const double* x = r.x->data(Depth::begin);
    const double* v = r.v->data(Depth::begin);
    const double* w = r.w->data(Depth::begin);
    const double* q = r.q->data(Depth::begin);
    double* px = r.px->data();
    double* pq = r.pq->data();
    double* travel = r.travel->data();
    double g_norm = 0;
    for (double gk : c.gravity) g_norm += gk * gk;
    g_norm = std::sqrt(g_norm);
    const int nr = d == 2 ? 1 : 3;
    for (std::size_t b = 0; b < nb; ++b) {
      // How far the body may travel and turn in the step (from its start velocity, with
      // margin): contacts are looked for that much further, so a fast body does not tunnel.
      double v2 = 0, w2 = 0;
      for (int k = 0; k < d; ++k) v2 += v[d * b + k] * v[d * b + k];
      for (int k = 0; k < nr; ++k) w2 += w[nr * b + k] * w[nr * b + k];
      travel[2 * b] = 2 * c.h * std::sqrt(v2) + c.h * c.h * g_norm;
      travel[2 * b + 1] = 2 * c.h * std::sqrt(w2);
      for (int k = 0; k < d; ++k) px[d * b + k] = x[d * b + k] + a * v[d * b + k];
      if (d == 2) {
        pq[b] = q[b] + a * w[b];
      } else {
        // q_θ = exp(a ω / 2) ⊗ q⁻ (ω in the world frame); first order is enough for a
        // detection configuration, renormalised.
        const double* qb = q + 4 * b;
        const double* wb = w + 3 * b;
        const double p[4] = {1, 0.5 * a * wb[0], 0.5 * a * wb[1], 0.5 * a * wb[2]};
        double r[4] = {p[0] * qb[0] - p[1] * qb[1] - p[2] * qb[2] - p[3] * qb[3],
                       p[0] * qb[1] + p[1] * qb[0] + p[2] * qb[3] - p[3] * qb[2],
                       p[0] * qb[2] - p[1] * qb[3] + p[2] * qb[0] + p[3] * qb[1],
                       p[0] * qb[3] + p[1] * qb[2] - p[2] * qb[1] + p[3] * qb[0]};
        const double n = 1 / std::sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2] + r[3] * r[3]);
        for (int k = 0; k < 4; ++k) pq[4 * b + k] = r[k] * n;
      }
    }
  }

  bool compact_inverse(const State& st, std::size_t body, double* M) const override {
    const int d = st.dimension();
    const int k = d == 2 ? 3 : 6;
    InverseFields other;
    const InverseFields& f = resolved(inverse_fields_, st, other);
    const auto b = static_cast<std::size_t>(f.first_node->data()[body]);  // st.body(body).first_node
    for (int i = 0; i < k * k; ++i) M[i] = 0;
    const double im = f.inverse_mass->row(b)[0];
    if (im == 0) return true;  // fixed
    const double* ii = f.inverse_inertia->row(b).data();
    for (int i = 0; i < d; ++i) M[i * k + i] = im;
    if (d == 2) {
      M[8] = ii[0];
    } else {
      double Rm[9], A[9], Iw[9];
      quat_to_matrix(f.orientation->row(b, Depth::begin).data(), Rm);
      // Iw = R I⁻¹ Rᵀ
      const double S[9] = {ii[0], ii[3], ii[4], ii[3], ii[1], ii[5], ii[4], ii[5], ii[2]};
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) A[i * 3 + j] = Rm[i * 3 + 0] * S[0 * 3 + j] + Rm[i * 3 + 1] * S[3 + j] + Rm[i * 3 + 2] * S[6 + j];
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) Iw[i * 3 + j] = A[i * 3 + 0] * Rm[j * 3 + 0] + A[i * 3 + 1] * Rm[j * 3 + 1] + A[i * 3 + 2] * Rm[j * 3 + 2];
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) M[(3 + i) * k + 3 + j] = Iw[i * 3 + j];
    }
    // An imposed component has infinite mass: no impulse changes it.
    if (f.imposed) {
      const double* imp = f.imposed->row(b).data();
      for (int i = 0; i < k; ++i)
        if (!std::isnan(imp[i]))
          for (int j = 0; j < k; ++j) M[i * k + j] = M[j * k + i] = 0;
    }
    return true;
  }

  void apply_inverse(const State& st, std::size_t body, int columns, const double* in, double* out) const override {
    const int k = st.dimension() == 2 ? 3 : 6;
    double M[36];
    compact_inverse(st, body, M);
    for (int c = 0; c < columns; ++c)
      for (int i = 0; i < k; ++i) {
        double s = 0;
        for (int j = 0; j < k; ++j) s += M[i * k + j] * in[c * k + j];
        out[c * k + i] = s;
      }
  }

 private:
  /// The fields compact_inverse() reads for every body a contact touches, resolved once
  /// (prepare; moreau/field_cache.hpp) instead of looked up by name at each call: st.body()
  /// and four field lookups a body were about a sixth of a 10⁴-sphere step's assembly.
  /// Another State (none in a run) is looked up.
  struct InverseFields {
    FieldCacheKey cache_key;  // of the node set
    const Field *first_node = nullptr, *inverse_mass = nullptr, *inverse_inertia = nullptr, *orientation = nullptr,
                *imposed = nullptr;
    static InverseFields of(const State& st) {
      const EntitySet& s = st.set(R::nodes);
      InverseFields f;
      f.first_node = &st.set(sets::bodies).field(body_fields::first_node);
      f.inverse_mass = &s.field(R::inverse_mass);
      f.inverse_inertia = &s.field(R::inverse_inertia);
      if (st.dimension() == 3) f.orientation = &s.field(R::orientation);
      f.imposed = s.find(R::imposed_velocity);  // only with drivers or hooks (Needed::imposed)
      f.cache_key.take(st, s);
      return f;
    }
  };
  InverseFields inverse_fields_;

  /// The node fields the step loops read, resolved once (moreau/field_cache.hpp: again for
  /// another State or when a field is declared later) instead of by name at every stage:
  /// the two map lookups (set, field) per field, 17 fields in free_velocity and
  /// update_dofs, were a fifth of a one-body step's CPU time (block_on_incline_2d). The
  /// optional ones (find()) are null when the scene does not need them.
  struct NodeFields {
    FieldCacheKey cache_key;
    EntitySet* nodes = nullptr;
    Field *x = nullptr, *v = nullptr, *w = nullptr, *q = nullptr, *vf = nullptr, *wf = nullptr, *im = nullptr,
          *ii = nullptr, *I = nullptr, *F = nullptr, *T = nullptr, *P = nullptr, *imp = nullptr, *px = nullptr,
          *pq = nullptr, *travel = nullptr;
    static NodeFields of(State& st) {
      NodeFields r;
      r.nodes = &st.set(R::nodes);
      EntitySet& s = *r.nodes;
      r.x = s.find(R::position);
      r.v = s.find(R::velocity);
      r.w = s.find(R::angular_velocity);
      r.q = s.find(st.dimension() == 2 ? R::angle : R::orientation);
      r.vf = s.find(R::free_velocity);
      r.wf = s.find(R::free_angular_velocity);
      r.im = s.find(R::inverse_mass);
      r.ii = s.find(R::inverse_inertia);
      r.I = s.find(R::inertia);
      r.F = s.find(R::force);
      r.T = s.find(R::torque);
      r.P = s.find(R::reaction);
      r.imp = s.find(R::imposed_velocity);
      r.px = s.find(R::detection_position);
      r.pq = s.find(R::detection_rotation);
      r.travel = s.find(R::travel);
      r.cache_key.take(st, s);
      return r;
    }
  };
  NodeFields node_fields_;

  static double* ptr(Field* f, Depth d = Depth::end) { return f ? f->data(d) : nullptr; }

  Fields fields(State& st, bool forces, bool impulses) {
    const NodeFields& r = resolved(node_fields_, st);
    Fields f{};
    f.x0 = ptr(r.x, Depth::begin);
    f.x1 = ptr(r.x, Depth::end);
    f.v0 = ptr(r.v, Depth::begin);
    f.v1 = ptr(r.v, Depth::end);
    f.w0 = ptr(r.w, Depth::begin);
    f.w1 = ptr(r.w, Depth::end);
    f.q0 = ptr(r.q, Depth::begin);
    f.q1 = ptr(r.q, Depth::end);
    f.vf = ptr(r.vf);
    f.wf = ptr(r.wf);
    f.im = ptr(r.im);
    f.ii = ptr(r.ii);
    f.I = ptr(r.I);
    if (forces) {
      f.F = ptr(r.F);
      f.T = ptr(r.T);
    }
    f.P = impulses ? ptr(r.P) : nullptr;
    f.imp = ptr(r.imp);
    f.n = r.nodes->rows();
    return f;
  }

  static void free_2d(const StepContext& c, const Fields& f) {
    const std::size_t n = f.n;
    const double h = c.h, gx = c.gravity[0], gy = c.gravity[1];
    for (std::size_t i = 0; i < n; ++i) {
      const double im = f.im[i];
      if (im == 0) {  // fixed
        f.vf[2 * i] = f.vf[2 * i + 1] = f.wf[i] = 0;
      } else {
        double ax = gx, ay = gy, alpha = 0;
        if (f.F) {
          ax += im * f.F[2 * i];
          ay += im * f.F[2 * i + 1];
          alpha = f.ii[i] * f.T[i];
        }
        f.vf[2 * i] = f.v0[2 * i] + h * ax;
        f.vf[2 * i + 1] = f.v0[2 * i + 1] + h * ay;
        f.wf[i] = f.w0[i] + h * alpha;
      }
      if (f.imp) impose(f.imp + 3 * i, f.vf + 2 * i, 2, f.wf + i, 1);
    }
  }

  static void update_2d(const StepContext& c, const Fields& f) {
    const std::size_t n = f.n;
    const double h = c.h, a = h * (1 - c.theta), b = h * c.theta;
    for (std::size_t i = 0; i < n; ++i) {
      double vx = f.vf[2 * i], vy = f.vf[2 * i + 1], w = f.wf[i];
      if (f.P && f.im[i] != 0) {
        vx += f.im[i] * f.P[3 * i];
        vy += f.im[i] * f.P[3 * i + 1];
        w += f.ii[i] * f.P[3 * i + 2];
      }
      if (f.imp) {
        double v[2] = {vx, vy};
        impose(f.imp + 3 * i, v, 2, &w, 1);
        vx = v[0];
        vy = v[1];
      }
      f.v1[2 * i] = vx;
      f.v1[2 * i + 1] = vy;
      f.w1[i] = w;
      f.x1[2 * i] = f.x0[2 * i] + a * f.v0[2 * i] + b * vx;
      f.x1[2 * i + 1] = f.x0[2 * i + 1] + a * f.v0[2 * i + 1] + b * vy;
      f.q1[i] = f.q0[i] + a * f.w0[i] + b * w;
    }
  }

  static void free_3d(const StepContext& c, const Fields& f) {
    const std::size_t n = f.n;
    const double h = c.h, ht = c.h * c.theta;
    const double g[3] = {c.gravity[0], c.gravity[1], c.gravity[2]};
    for (std::size_t i = 0; i < n; ++i) {
      double* vf = f.vf + 3 * i;
      double* wf = f.wf + 3 * i;
      const double im = f.im[i];
      if (im == 0) {
        vf[0] = vf[1] = vf[2] = wf[0] = wf[1] = wf[2] = 0;
        if (f.imp) impose(f.imp + 6 * i, vf, 3, wf, 3);
        continue;
      }
      const double* v = f.v0 + 3 * i;
      for (int k = 0; k < 3; ++k) vf[k] = v[k] + h * (g[k] + (f.F ? im * f.F[3 * i + k] : 0.0));

      const double* I = f.I + 6 * i;
      const double* ii = f.ii + 6 * i;
      const double* w = f.w0 + 3 * i;
      const bool isotropic = I[0] == I[1] && I[1] == I[2] && I[3] == 0 && I[4] == 0 && I[5] == 0;
      if (isotropic) {
        // No gyroscopic term: ω_free = ω + h I⁻¹ τ in any frame.
        for (int k = 0; k < 3; ++k) wf[k] = w[k] + (f.T ? h * ii[0] * f.T[3 * i + k] : 0.0);
      } else {
        const double* q = f.q0 + 4 * i;
        const double qc[4] = {q[0], -q[1], -q[2], -q[3]};  // world → body
        double W[3], IW[3], WxIW[3], rhs[3], dW[3];
        quat_rotate(qc, w, W);
        sym_mul(I, W, IW);
        cross(W, IW, WxIW);
        double Tb[3] = {0, 0, 0};
        if (f.T) quat_rotate(qc, f.T + 3 * i, Tb);
        for (int k = 0; k < 3; ++k) rhs[k] = h * (Tb[k] - WxIW[k]);
        // A = I + hθ J, J = ∂(Ω×IΩ)/∂Ω = [Ω]× I − [IΩ]×
        const double Im[9] = {I[0], I[3], I[4], I[3], I[1], I[5], I[4], I[5], I[2]};
        const double Wx[9] = {0, -W[2], W[1], W[2], 0, -W[0], -W[1], W[0], 0};
        const double Lx[9] = {0, -IW[2], IW[1], IW[2], 0, -IW[0], -IW[1], IW[0], 0};
        double A[9];
        for (int r = 0; r < 3; ++r)
          for (int s = 0; s < 3; ++s) {
            double j = Wx[r * 3] * Im[s] + Wx[r * 3 + 1] * Im[3 + s] + Wx[r * 3 + 2] * Im[6 + s] - Lx[r * 3 + s];
            A[r * 3 + s] = Im[r * 3 + s] + ht * j;
          }
        solve3(A, rhs, dW);
        for (int k = 0; k < 3; ++k) W[k] += dW[k];
        quat_rotate(q, W, wf);  // world axes at the start of the step
      }
      if (f.imp) impose(f.imp + 6 * i, vf, 3, wf, 3);
    }
  }

  static void update_3d(const StepContext& c, const Fields& f) {
    const std::size_t n = f.n;
    const double h = c.h, a = h * (1 - c.theta), b = h * c.theta, th = c.theta;
    for (std::size_t i = 0; i < n; ++i) {
      double v[3] = {f.vf[3 * i], f.vf[3 * i + 1], f.vf[3 * i + 2]};
      double w[3] = {f.wf[3 * i], f.wf[3 * i + 1], f.wf[3 * i + 2]};
      const double* q0 = f.q0 + 4 * i;
      double* q1 = f.q1 + 4 * i;
      const bool fixed = f.im[i] == 0;
      if (f.P && !fixed) {
        // Contact impulses: Δv = P/m, Δω̃ = R⁻ I⁻¹ R⁻ᵀ L.
        double Rm[9], Lb[3], dW[3], dw[3];
        quat_to_matrix(q0, Rm);
        const double* ii = f.ii + 6 * i;
        for (int k = 0; k < 3; ++k) v[k] += f.im[i] * f.P[6 * i + k];
        mul_transpose(Rm, f.P + 6 * i + 3, Lb);
        sym_mul(ii, Lb, dW);
        mul(Rm, dW, dw);
        for (int k = 0; k < 3; ++k) w[k] += dw[k];
      }
      if (f.imp) impose(f.imp + 6 * i, v, 3, w, 3);
      const double* x0 = f.x0 + 3 * i;
      const double* v0 = f.v0 + 3 * i;
      for (int k = 0; k < 3; ++k) {
        f.v1[3 * i + k] = v[k];
        f.x1[3 * i + k] = x0[k] + a * v0[k] + b * v[k];
      }
      if (fixed) {
        for (int k = 0; k < 4; ++k) q1[k] = q0[k];
        for (int k = 0; k < 3; ++k) f.w1[3 * i + k] = w[k];
        continue;
      }
      // Rotation by h Ω_θ in the body frame, i.e. by φ = h[(1−θ)ω⁻ + θω̃⁺] in world axes
      // at the start of the step: q⁺ = exp(φ/2) ⊗ q⁻, and ω⁺ = R⁺ Ω⁺ = exp(φ/2) ω̃⁺.
      const double* w0 = f.w0 + 3 * i;
      const double phi[3] = {h * ((1 - th) * w0[0] + th * w[0]), h * ((1 - th) * w0[1] + th * w[1]),
                             h * ((1 - th) * w0[2] + th * w[2])};
      double p[4];
      exp_half(phi, p);
      quat_mul_normalised(p, q0, q1);
      quat_rotate(p, w, f.w1 + 3 * i);
      if (f.imp) impose(f.imp + 6 * i, f.v1 + 3 * i, 3, f.w1 + 3 * i, 3);  // imposed in world axes at t⁺
    }
  }

  /// Overwrites the imposed (non-NaN) components: linear then angular.
  static void impose(const double* imp, double* v, int nv, double* w, int nw) {
    for (int k = 0; k < nv; ++k)
      if (!std::isnan(imp[k])) v[k] = imp[k];
    for (int k = 0; k < nw; ++k)
      if (!std::isnan(imp[nv + k])) w[k] = imp[nv + k];
  }
};

MOREAU_REGISTER(Theta, "theta")

}  // namespace

MOREAU_PLUGIN_LIBRARY("moreau_integrator_theta")
