#include "apgd_core.hpp"

#include "../work.hpp"
#include "rigid_frames.hpp"
#include "scaled_factor.hpp"

#include <cmath>
#include <cstring>
#include <memory>
#include <moreau/contact_error.hpp>
#include <moreau/factor_matrix.hpp>
#include <vector>

namespace moreau::apgd {

namespace {
inline void project_cone(int d, double mu, const double* x, double* out) { project_on_cone(d, mu, x, out); }

/// x strictly inside the cone ‖x_T‖ ≤ μ x_n (not on its boundary, not at its apex). A
/// projection lands on the boundary to rounding; the margin keeps such a point outside.
/// Squared, without a square root (a root per contact cost 5 % of a step at 256 contacts).
template <int D>
inline bool strictly_inside(double mu, const double* x) {
  const double tt = D == 2 ? x[1] * x[1] : x[1] * x[1] + x[2] * x[2], n = (1 - 1e-9) * mu * x[0];
  return x[0] > 0 && tt < n * n;
}

/// inside[α] = strictly_inside(μ_α, x_α) for every contact (projected_step's status of x).
void inside_status(const LocalProblem& P, const Eigen::VectorXd& x, std::vector<unsigned char>& inside) {
  const int d = P.dim;
  inside.resize(static_cast<std::size_t>(P.contacts()));
  for (Eigen::Index a = 0; a < P.contacts(); ++a)
    inside[static_cast<std::size_t>(a)] = d == 2 ? strictly_inside<2>(P.mu[a], x.data() + 2 * a) : strictly_inside<3>(P.mu[a], x.data() + 3 * a);
}

void project_all(const LocalProblem& P, const Eigen::VectorXd& x, Eigen::VectorXd& out) {
  const int d = P.dim;
  for (Eigen::Index a = 0; a < P.contacts(); ++a) project_cone(d, P.mu[a], x.data() + a * d, out.data() + a * d);
}
/// Products by W: by the matrix when given, else through its factor W = H M⁻¹ Hᵀ (the
/// time-stepper's form, which `auto` passes without assembling W: for 10⁵ spheres W has
/// ~3·10⁷ entries, the factor's H blocks a tenth of that): for 3D rigid bodies packed as
/// frames and lever arms (rigid_frames.hpp: 15 doubles a contact), for other rigid bodies
/// with the inverse masses folded in (scaled_factor.hpp), else by multiply_w.
class WProduct {
 public:
  /// The products of P from now on (its factor packed when they go through it; the packed
  /// arrays of an earlier problem are reused).
  void bind(const LocalProblem& P) {
    P_ = &P;
    through_factor_ = P.W.rows() != P.q.size() && P.factor.present();
    frames_ = through_factor_ && rigid_frames_.prepare(P.dim, P.factor);
    scaled_ = through_factor_ && !frames_ && scaled_factor_.prepare(P.dim, P.factor);
  }
  bool through_factor() const { return through_factor_; }
  /// Packed (rigid frames or H̃): its cost model (WorkCosts::scaled_factor_product).
  bool scaled() const { return scaled_ || frames_; }

  void apply(const Eigen::VectorXd& x, Eigen::VectorXd& out) {
    if (!through_factor_) {
      out = P_->W * x;
      return;
    }
    if (frames_) {
      rigid_frames_.multiply(x, out);
      return;
    }
    if (scaled_) {
      scaled_factor_.multiply(x, out);
      return;
    }
    multiply_w(P_->dim, P_->factor, x, out, impulse_, dv_);
  }

  /// W's diagonal.
  Eigen::VectorXd diagonal() const {
    if (!through_factor_) return P_->W.diagonal();
    if (frames_) return rigid_frames_.diagonal();
    if (scaled_) return scaled_factor_.diagonal();
    const BodyFactor& f = P_->factor;
    const int d = P_->dim, k = f.k;
    Eigen::VectorXd w = Eigen::VectorXd::Zero(P_->q.size());
    for (std::size_t a = 0; a < f.body.size() / 2; ++a)
      for (int side = 0; side < 2; ++side) {
        const int b = f.body[2 * a + side];
        if (b < 0) continue;
        const double* H = &f.H[(a * 2 + side) * d * k];
        const double* Mi = &f.inverse_mass[static_cast<std::size_t>(b) * k * k];
        for (int i = 0; i < d; ++i) {
          double s = 0;
          for (int l = 0; l < k; ++l)
            for (int m = 0; m < k; ++m) s += H[i * k + l] * Mi[l * k + m] * H[i * k + m];
          w[static_cast<Eigen::Index>(a * d + i)] += s;
        }
      }
    for (std::size_t i = 0; i < f.diagonal.size(); ++i) w[static_cast<Eigen::Index>(i)] += f.diagonal[i];
    return w;
  }

 private:
  const LocalProblem* P_ = nullptr;
  bool through_factor_ = false, scaled_ = false, frames_ = false;
  RigidFrames rigid_frames_;  ///< 3D rigid bodies (rigid_frames.hpp)
  ScaledFactor scaled_factor_;
  std::vector<double> impulse_, dv_;
};

/// The hot loops of one APGD step, fused per contact (one pass each instead of one per
/// vector operation: at 10⁴ spheres the vector passes cost as much as the products).
/// The projected step from y along g (g = W y + q + De Saxcé shift, computed here when
/// `with_g`): x⁺ = P_K(y − D⁻¹ g / L) with P_K the projection in D's metric,
/// dl = x⁺ − y; returns Σ_α dl_αᵀ D_α dl_α; inside_next[α]: x⁺_α strictly inside its cone.
/// The shift μ‖u_T‖ e_n is added only at the contacts whose last iterate x is not strictly
/// inside the cone (inside[α] = 0: on its boundary or at its apex). Where the answer is
/// inside the cone, u = 0 there and the shift vanishes at the answer whatever it is during
/// the iteration: it changes no fixed point. Added everywhere it is a term of gain up to
/// μ‖W_T‖/L on the step that no gradient of a convex function has: with μ ≥ 1 it made the
/// iteration expansive (`czm`'s bonds, μ = 2 in a cone that never binds: bonded_beam_2d's
/// problems stayed at error 0.1 after 10⁴ steps; docs/solvers.md, `apgd`).
/// `Split` false: D_α is one scalar per contact, s[a], and P_K the Euclidean projection.
/// `Split` true: D_α = diag(d_n, d_t, d_t), s[3a..3a+2] = (d_n, d_t, ρ = √(d_t / d_n)).
/// In the coordinates (r_n, ρ r_t) the D-metric is Euclidean (up to the factor d_n) and the
/// cone ‖r_t‖ ≤ μ r_n is the cone of coefficient μρ, so the projection stays exact: project
/// (t_n, ρ t_t) on that cone, divide its tangential part by ρ.
template <int D, bool Split>
double projected_step(Eigen::Index nc, const double* mu, const double* s, double invL, const double* y, const double* Wy,
                      const double* q, bool with_g, double* g, double* xn, double* dl, const unsigned char* inside,
                      unsigned char* inside_next) {
  double rhs = 0;
  for (Eigen::Index a = 0; a < nc; ++a) {
    const Eigen::Index o = a * D;
    if (with_g) {
      for (int i = 0; i < D; ++i) g[o + i] = Wy[o + i] + q[o + i];
      if (!inside[a]) g[o] += mu[a] * (D == 2 ? std::fabs(g[o + 1]) : std::sqrt(g[o + 1] * g[o + 1] + g[o + 2] * g[o + 2]));
    }
    double t[D], p[D];
    if constexpr (Split) {
      const double dn = s[3 * a], dt = s[3 * a + 1], rho = s[3 * a + 2];
      const double cn = invL / dn, ct = invL / dt;
      t[0] = y[o] - cn * g[o];
      for (int i = 1; i < D; ++i) t[i] = rho * (y[o + i] - ct * g[o + i]);
      project_on_cone(D, mu[a] * rho, t, p);
      inside_next[a] = strictly_inside<D>(mu[a] * rho, p);
      const double back = 1 / rho;
      for (int i = 1; i < D; ++i) p[i] *= back;
      double en = p[0] - y[o], et = 0;
      xn[o] = p[0];
      dl[o] = en;
      for (int i = 1; i < D; ++i) {
        xn[o + i] = p[i];
        const double e = p[i] - y[o + i];
        dl[o + i] = e;
        et += e * e;
      }
      rhs += dn * en * en + dt * et;
    } else {
      const double c = invL / s[a];
      for (int i = 0; i < D; ++i) t[i] = y[o + i] - c * g[o + i];
      project_on_cone(D, mu[a], t, p);
      inside_next[a] = strictly_inside<D>(mu[a], p);
      double sum = 0;
      for (int i = 0; i < D; ++i) {
        xn[o + i] = p[i];
        const double e = p[i] - y[o + i];
        dl[o + i] = e;
        sum += e * e;
      }
      rhs += s[a] * sum;
    }
  }
  return rhs;
}

/// projected_step for the problem's dimension and scaling.
double projected_step(int d, bool split, Eigen::Index nc, const double* mu, const double* s, double invL, const double* y,
                      const double* Wy, const double* q, bool with_g, double* g, double* xn, double* dl, const unsigned char* inside,
                      unsigned char* inside_next) {
  if (d == 2)
    return split ? projected_step<2, true>(nc, mu, s, invL, y, Wy, q, with_g, g, xn, dl, inside, inside_next)
                 : projected_step<2, false>(nc, mu, s, invL, y, Wy, q, with_g, g, xn, dl, inside, inside_next);
  return split ? projected_step<3, true>(nc, mu, s, invL, y, Wy, q, with_g, g, xn, dl, inside, inside_next)
               : projected_step<3, false>(nc, mu, s, invL, y, Wy, q, with_g, g, xn, dl, inside, inside_next);
}

/// Wxn = Wy + Wd; returns gᵀ(x⁺ − x) (the restart test).
double advance(Eigen::Index n, const double* Wy, const double* Wd, const double* g, const double* xn, const double* x, double* Wxn) {
  double up = 0;
  for (Eigen::Index i = 0; i < n; ++i) {
    Wxn[i] = Wy[i] + Wd[i];
    up += g[i] * (xn[i] - x[i]);
  }
  return up;
}

/// y = x⁺ + β(x⁺ − x), Wy likewise; returns Σ_α ‖natural map_α‖² at x⁺ (u = W x⁺ + q),
/// or 0 without it (`Error` false: each contact's natural map is a cone projection, about
/// a sixth of an iteration).
template <int D, bool Error>
double extrapolate(Eigen::Index nc, const double* mu, double beta, const double* xn, const double* x, const double* Wxn,
                   const double* Wx, const double* q, double* y, double* Wy) {
  double sum = 0;
  for (Eigen::Index a = 0; a < nc; ++a) {
    const Eigen::Index o = a * D;
    double u[D];
    for (int i = 0; i < D; ++i) {
      y[o + i] = xn[o + i] + beta * (xn[o + i] - x[o + i]);
      Wy[o + i] = Wxn[o + i] + beta * (Wxn[o + i] - Wx[o + i]);
      u[i] = Wxn[o + i] + q[o + i];
    }
    if constexpr (Error) sum += contact_natural_map_squared(D, mu[a], xn + o, u);
  }
  return sum;
}

}  // namespace

/// The products by W of one problem and what depends on W only: the scaling D (per
/// contact: a scalar, its mean diagonal of W; or, `Scaling::normal_tangent`, its normal
/// diagonal entry and the mean of its tangential ones) and the cost of a product. Packed
/// once per problem, kept in State::products for later calls on the same problem; a call
/// on another problem packs it into the same arrays (prepare()).
class Products {
 public:
  Products(const LocalProblem& P, Scaling sc) { prepare(P, sc); }
  void prepare(const LocalProblem& P, Scaling sc) {
    problem = &P;
    scaling = sc;
    W.bind(P);
    const int d = P.dim;
    const Eigen::Index nc = P.contacts(), n = d * nc;
    const Eigen::VectorXd diag = W.diagonal();
    double mean_diag = 0;
    for (Eigen::Index i = 0; i < n; ++i) mean_diag += diag[i];
    mean_diag /= static_cast<double>(n);
    if (!(mean_diag > 0)) mean_diag = 1;
    // An entry that is not positive (a direction no body moves in) takes the mean diagonal.
    const auto positive = [&](double t) { return t > 1e-12 * mean_diag ? t : mean_diag; };
    if (split()) {
      s.resize(3 * nc);
      for (Eigen::Index a = 0; a < nc; ++a) {
        double t = 0;
        for (int k = 1; k < d; ++k) t += diag[a * d + k];
        const double dn = positive(diag[a * d]), dt = positive(t / (d - 1));
        s[3 * a] = dn;
        s[3 * a + 1] = dt;
        s[3 * a + 2] = std::sqrt(dt / dn);
      }
    } else {
      s.resize(nc);
      for (Eigen::Index a = 0; a < nc; ++a) {
        double t = 0;
        for (int k = 0; k < d; ++k) t += diag[a * d + k];
        s[a] = positive(t / d);
      }
    }
    cost = W.scaled() ? WorkCosts::packed(P) : WorkCosts::of(P, W.through_factor());
    denominator = error_denominator(P);
  }
  bool of(const LocalProblem& P) const { return problem == &P && s.size() == (split() ? 3 : 1) * P.contacts(); }
  bool of(const LocalProblem& P, Scaling sc) const { return scaling == sc && of(P); }
  bool split() const { return scaling == Scaling::normal_tangent; }

  const LocalProblem* problem = nullptr;
  WProduct W;
  Scaling scaling = Scaling::contact;
  Eigen::VectorXd s;  ///< the scaling D per contact (projected_step: 1 or 3 values a contact)
  WorkCosts cost;
  double denominator = 1;  ///< error_denominator(P) (a pass over q: not repeated at each slice)
  /// solve()'s work vectors beside the state's x, y, W x, W y (kept for their memory).
  Eigen::VectorXd xn, Wxn, g, dl, Wd, best;
  std::vector<unsigned char> inside, inside_next;  ///< per contact: x, x⁺ strictly inside the cone
};

bool velocities(const State& state, const LocalProblem& P, const Eigen::VectorXd& x, Eigen::VectorXd& u) {
  if (!state.products || !state.products->of(P)) return false;
  state.products->W.apply(x, u);
  u += P.q;
  return true;
}

State::State() = default;
State::~State() = default;
State::State(State&&) noexcept = default;
State& State::operator=(State&&) noexcept = default;

SolverReport solve(const LocalProblem& P, const Options& o, Eigen::VectorXd& r, Eigen::VectorXd& u) {
  const int d = P.dim;
  const Eigen::Index nc = P.contacts(), n = d * nc;
  SolverReport rep;
  if (r.size() != n || !r.allFinite()) r = Eigen::VectorXd::Zero(n);
  if (nc == 0) {
    u = P.q;
    rep.converged = true;
    return rep;
  }
  std::unique_ptr<Products> kept;
  const bool packed = o.state && o.same_problem && o.state->products && o.state->products->of(P, o.scaling);
  if (packed) {
    kept = std::move(o.state->products);
  } else if (o.state && o.state->products) {  // another problem: packed into the last one's arrays
    kept = std::move(o.state->products);
    kept->prepare(P, o.scaling);
  } else {
    kept = std::make_unique<Products>(P, o.scaling);
  }
  WProduct& W = kept->W;
  const double* scale = kept->s.data();
  const bool split = kept->split();
  const WorkCosts& cost = kept->cost;

  // The run's vectors: the kept state's and the products' (the last solve's memory, every
  // entry written before it is read).
  Eigen::VectorXd x, Wx, y, Wy;
  Eigen::VectorXd &xn = kept->xn, &Wxn = kept->Wxn, &g = kept->g, &dl = kept->dl, &Wd = kept->Wd, &best = kept->best;
  if (o.state) x.swap(o.state->x), y.swap(o.state->y), Wx.swap(o.state->Wx), Wy.swap(o.state->Wy);
  const bool resume = o.resume && o.state && x.size() == n;
  for (Eigen::VectorXd* v : {&x, &Wx, &y, &Wy, &xn, &Wxn, &g, &dl, &Wd}) v->resize(n);
  double L = 1, theta = 1;
  WorkMeter meter(o.max_work, o.work);
  double best_err = -1;
  if (resume) {  // x, W x and y, W y as the last call left them: nothing to compute
    const State& st = *o.state;
    L = st.L, theta = st.theta;
    best_err = st.err;
  } else {
    project_all(P, r, x);
    // The caller's product of this start (Options::start_wr), when x is its start bit for bit.
    const bool handed = o.start_r && o.start_wr && o.start_r->size() == n && o.start_wr->size() == n &&
                        std::memcmp(o.start_r->data(), x.data(), sizeof(double) * static_cast<std::size_t>(n)) == 0;
    if (handed) {
      Wx = *o.start_wr;
      // Its error too, when u is computed again on exit anyway (o.velocities or recompute).
      if (o.start_error >= 0 && (o.velocities || o.recompute_error)) {
        best_err = o.start_error;
        meter.add(cost.error);
      }
    } else {
      W.apply(x, Wx);
    }
    y = x;
    Wy = Wx;
  }
  bool u_is_start = false;  // u = W x + q of the start, x and W x unchanged since (no step)
  if (!(best_err >= 0)) {  // a start, or a resumed run whose last step was not measured
    u = Wx + P.q;
    best_err = natural_map_error(P, x, u);
    meter.add(cost.error);
    u_is_start = true;
  }
  // The start's product and copies; packing the factor (H L per contact side) costs about a
  // product.
  const double packing = W.scaled() && !packed ? cost.product : 0;
  if (resume) {
    if (packing > 0) meter.add(packing);
  } else {
    meter.add(cost.product + packing + 2 * cost.vector);
  }
  // The error at x: kept in the state for a resumed call (the same sum as natural_map_error's,
  // in the same order: a resumed call starts from the number it would recompute).
  double x_err = best_err;
  // The best iterate is x itself until an iterate is worse than the one before: copied only
  // then (not at every step).
  bool best_is_x = true;
  const double denominator = kept->denominator;
  std::vector<unsigned char>&inside = kept->inside, &inside_next = kept->inside_next;
  // A resumed run keeps the status its last step gave x (the products, which hold it, are
  // the state's); otherwise it is taken from x.
  if (!resume || inside.size() != static_cast<std::size_t>(nc)) inside_status(P, x, inside);
  inside_next.resize(inside.size());
  const double* mu = P.mu.data();
  const double* q = P.q.data();
  for (long it = 1; it <= o.max_iterations && best_err > o.tolerance; ++it) {
    rep.iterations = it;
    u_is_start = false;
    bool ok = false;
    int backtracks = 0;
    for (int bt = 0; bt < 60; ++bt, ++backtracks) {
      const double rhs = L * projected_step(d, split, nc, mu, scale, 1 / L, y.data(), Wy.data(), q, bt == 0, g.data(), xn.data(), dl.data(), inside.data(),
                                           inside_next.data());
      W.apply(dl, Wd);
      const double lhs = dl.dot(Wd);
      if (!std::isfinite(lhs)) break;
      if (lhs <= rhs * (1 + 1e-12) + 1e-300) {
        ok = true;
        break;
      }
      L *= 2;
    }
    if (!ok) break;
    const double uphill = advance(n, Wy.data(), Wd.data(), g.data(), xn.data(), x.data(), Wxn.data());
    const double theta_n = 0.5 * (-theta * theta + theta * std::sqrt(theta * theta + 4));
    double beta = theta * (1 - theta) / (theta * theta + theta_n);
    theta = theta_n;
    if (o.restart && uphill > 0) {  // the step goes uphill: restart the momentum
      beta = 0;
      theta = 1;
    }
    const bool check = it == 1 || it % o.check_every == 0;
    const double sum = check ? (d == 2 ? extrapolate<2, true>(nc, mu, beta, xn.data(), x.data(), Wxn.data(), Wx.data(), q, y.data(), Wy.data())
                                       : extrapolate<3, true>(nc, mu, beta, xn.data(), x.data(), Wxn.data(), Wx.data(), q, y.data(), Wy.data()))
                             : (d == 2 ? extrapolate<2, false>(nc, mu, beta, xn.data(), x.data(), Wxn.data(), Wx.data(), q, y.data(), Wy.data())
                                       : extrapolate<3, false>(nc, mu, beta, xn.data(), x.data(), Wxn.data(), Wx.data(), q, y.data(), Wy.data()));
    x.swap(xn);
    Wx.swap(Wxn);
    inside.swap(inside_next);
    L *= o.shrink;
    if (!check) {  // x⁺ not measured: not a candidate for the best iterate
      x_err = -1;
      if (best_is_x) {
        best = xn;
        best_is_x = false;
      }
      meter.add((1 + backtracks) * cost.product + 8 * cost.vector);
      if (meter.exhausted()) break;
      continue;
    }
    const double e = std::sqrt(sum) / denominator;
    if (!std::isfinite(e)) {
      x.swap(xn);  // x stays the last finite iterate (kept in the state)
      Wx.swap(Wxn);
      inside.swap(inside_next);
      break;
    }
    x_err = e;
    if (e < best_err) {
      best_err = e;
      best_is_x = true;
    } else if (best_is_x) {
      best = xn;  // the iterate before, the best, is overwritten by the next step
      best_is_x = false;
    }
    meter.add((1 + backtracks) * cost.product + cost.error + 8 * cost.vector);  // a product, one per backtrack
    if (meter.exhausted()) break;
  }
  r = best_is_x ? x : best;
  if (!o.recompute_error && !o.velocities) {
    rep.error = best_err;  // as the iteration measured it; u is not computed
  } else if (o.recompute_error || !best_is_x) {
    W.apply(r, u);
    u += P.q;
    meter.add(cost.product);
    rep.error = natural_map_error(P, r, u);
  } else {
    if (!u_is_start) u = Wx + P.q;  // as the iteration measured it (a call without a step, auto's start check, has it)
    rep.error = best_err;
  }
  rep.converged = rep.error <= o.tolerance;
  if (o.state) {
    State& st = *o.state;
    st.x.swap(x), st.y.swap(y), st.Wx.swap(Wx), st.Wy.swap(Wy), st.L = L, st.theta = theta, st.err = x_err;
    st.products = std::move(kept);
  }
  return rep;
}

}  // namespace moreau::apgd
