// W = H LHS⁻¹ Hᵀ built from the modelizations' pieces (kernel/contact/contact_assembly),
// against a direct dense computation, in a mixed scene: a rigid ball, a fixed rigid floor
// and a chain of three point masses joined by springs (tests/mixed), so that contacts on
// the chain are coupled through its LHS = M + h²θ²K. Also q = H v_free, the reactions
// Hᵀ r given back, and one step's velocity update against the dense solution of the
// frictionless problem with every contact closed; and the factored form for rigid bodies.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <moreau/integrator.hpp>
#include <moreau/modelization.hpp>
#include <moreau/rigid_fields.hpp>

#include "kernel/contact/contact_assembly.hpp"
#include "kernel/contact/local_frame.hpp"
#include "kernel/scene/validate.hpp"

using namespace moreau;
using namespace moreau::kernel;
using nlohmann::json;

namespace {

template <class T>
std::unique_ptr<T> create(const std::string& name, const BuildContext& ctx) {
  for (auto& r : detail::local_registrations())
    if (r.kind == T::kind && r.name == name)
      return std::unique_ptr<T>(dynamic_cast<T*>(r.factory(Params(json::object(), "/test"), ctx).release()));
  throw std::logic_error("no plugin " + name + " linked into the test");
}

/// A rigid ball (m, isotropic I), a fixed rigid floor and a chain of three nodes along x
/// (node mass mc, springs k), in 2D or 3D, with velocities; after free_velocity and the
/// detection configuration of one step.
struct Mixed {
  int d;
  double h = 0.01, theta = 0.6, m = 2.0, I = 0.3, mc = 0.5, k = 400.0;
  State st;
  StepContext ctx;
  BuildContext build;
  std::unique_ptr<Modelization> rigid, chain;
  std::unique_ptr<Integrator> theta_int, chain_int;
  std::vector<ContactModel> models;

  explicit Mixed(int dim) : d(dim), st(dim), ctx{st} {
    build.dimension = d;
    build.time_step = h;
    ctx.h = h;
    ctx.theta = theta;
    ctx.gravity.assign(d, 0.0);
    ctx.gravity[1] = -9.81;
    rigid = create<Modelization>("rigid", build);
    chain = create<Modelization>("chain", build);
    theta_int = create<Integrator>("theta", build);
    chain_int = create<Integrator>("chain_theta", build);
    for (auto* mod : {rigid.get(), chain.get()}) {
      st.add_model({mod == rigid.get() ? "rigid" : "chain", mod->node_set(), mod->element_set(), mod->node_dofs(d)});
      for (const auto& f : mod->fields(d))
        if (f.components(d) > 0 && f.needed != Needed::forces && f.needed != Needed::imposed) st.declare(f);
    }
    st.add_bodies({{"ball", 0, 1, 0}, {"floor", 0, 1, 0}, {"chain", 1, 3, 2}});
    auto vec = [&](std::vector<double> v) {
      v.resize(d);
      return v;
    };
    init(*rigid, 0, {{"position", vec({0.1, 0.6, 0.05})}, {"velocity", vec({0.3, -1.0, 0.2})},
                     {"angular_velocity", d == 2 ? json(2.0) : json({1.0, -2.0, 0.5})}, {"mass", m},
                     {"inertia", d == 2 ? json(I) : json({I, I, I})}});
    init(*rigid, 1, {{"position", vec({0, -0.5, 0})}, {"fixed", true}});
    init(*chain, 2, {{"nodes", {vec({-0.5, 0.1, 0}), vec({0.0, 0.12, 0.01}), vec({0.5, 0.1, 0})}},
                     {"velocity", vec({0.2, -0.5, 0.1})}, {"node_mass", mc}, {"stiffness", k}});
    theta_int->prepare(st, *rigid);
    chain_int->prepare(st, *chain);
    // Stretch the chain a little so that springs pull.
    st.field("chain.nodes", "position").row(2, Depth::begin)[0] += 0.01;
    for (auto* i : {theta_int.get(), chain_int.get()}) i->free_velocity(ctx);
    for (auto* i : {theta_int.get(), chain_int.get()}) i->detection_configuration(ctx);
    models = {{rigid.get(), theta_int.get(), rigid->node_set(), rigid->node_dofs(d)},
              {chain.get(), chain_int.get(), chain->node_set(), chain->node_dofs(d)}};
  }

  void init(Modelization& mod, std::size_t body, const json& params) {
    std::vector<InputError> errors;
    Validation v{d, errors};
    json checked = validate_object(params, mod.body_schema(d), "/bodies", v);
    if (!errors.empty()) throw errors.front();
    mod.init_body(st, body, Params(checked, "/bodies"), std::nullopt, nullptr);
  }

  /// Contacts: chain node 0 and node 2 on the floor, the ball on chain node 1, the ball on
  /// the floor (normals from the second body toward the first).
  ContactSides contacts() const {
    ContactSides c;
    auto add = [&](int b0, int m0, std::size_t n0, int b1, int m1, std::size_t n1, std::vector<double> p, std::vector<double> n) {
      c.body.insert(c.body.end(), {b0, b1});
      c.model.insert(c.model.end(), {m0, m1});
      c.node.insert(c.node.end(), {n0, n1});
      p.resize(3, 0.0);
      c.point.insert(c.point.end(), p.begin(), p.end());
      double nn = 0;
      for (double x : n) nn += x * x;
      for (double& x : n) x /= std::sqrt(nn);
      if (d == 2) {
        auto f = local_frame_2d(n.data());
        for (auto& row : f) c.frame.insert(c.frame.end(), row.begin(), row.end());
      } else {
        auto f = local_frame_3d(n.data());
        for (auto& row : f) c.frame.insert(c.frame.end(), row.begin(), row.end());
      }
    };
    const std::vector<double> up = d == 2 ? std::vector<double>{0, 1} : std::vector<double>{0, 1, 0};
    const std::vector<double> tilt = d == 2 ? std::vector<double>{0.2, 1} : std::vector<double>{0.2, 1, -0.1};
    add(2, 1, 0, 1, 0, 1, {-0.5, 0.05, 0}, up);
    add(2, 1, 2, 1, 0, 1, {0.5, 0.05, 0.02}, up);
    add(0, 0, 0, 2, 1, 1, {0.05, 0.2, 0.03}, tilt);
    add(0, 0, 0, 1, 0, 1, {0.15, 0.3, 0.04}, up);
    return c;
  }

  // ---- The dense reference, from the definitions (not from the plugins' pieces) -------
  int k_rigid() const { return d == 2 ? 3 : 6; }
  int dofs() const { return 2 * k_rigid() + 3 * d; }  // ball, floor, chain
  int offset(int body) const { return body == 0 ? 0 : body == 1 ? k_rigid() : 2 * k_rigid(); }

  /// The chain's K from its rest directions.
  Eigen::MatrixXd stiffness() const {
    Eigen::MatrixXd K = Eigen::MatrixXd::Zero(3 * d, 3 * d);
    const double X[3][3] = {{-0.5, 0.1, 0}, {0.0, 0.12, 0.01}, {0.5, 0.1, 0}};
    for (int s = 0; s < 2; ++s) {
      Eigen::VectorXd e(d);
      for (int q = 0; q < d; ++q) e[q] = X[s + 1][q] - X[s][q];
      e.normalize();
      const Eigen::MatrixXd kee = k * e * e.transpose();
      K.block(s * d, s * d, d, d) += kee;
      K.block((s + 1) * d, (s + 1) * d, d, d) += kee;
      K.block(s * d, (s + 1) * d, d, d) -= kee;
      K.block((s + 1) * d, s * d, d, d) -= kee;
    }
    return K;
  }

  /// Dense LHS⁻¹ (the floor's block zero: fixed).
  Eigen::MatrixXd lhs_inverse() const {
    const int n = dofs(), kr = k_rigid();
    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n, n);
    for (int i = 0; i < d; ++i) A(i, i) = 1 / m;
    for (int i = d; i < kr; ++i) A(i, i) = 1 / I;
    // Chain: M + h²θ²K.
    const int c = 2 * kr;
    const Eigen::MatrixXd K = stiffness();
    const Eigen::MatrixXd L = mc * Eigen::MatrixXd::Identity(3 * d, 3 * d) + h * h * theta * theta * K;
    A.block(c, c, 3 * d, 3 * d) = L.inverse();
    return A;
  }

  /// Dense H (d rows per contact) from the frames, the lever arms at the detection
  /// configuration x⁻ + (1−θ)h v⁻, and the node the point is on.
  Eigen::MatrixXd dense_H(const ContactSides& c) const {
    const int nc = static_cast<int>(c.size()), kr = k_rigid();
    Eigen::MatrixXd H = Eigen::MatrixXd::Zero(nc * d, dofs());
    const double a = (1 - theta) * h;
    for (int al = 0; al < nc; ++al)
      for (int s = 0; s < 2; ++s) {
        const double sign = s == 0 ? 1 : -1;
        const int b = c.body[2 * al + s];
        const double* fr = &c.frame[al * d * d];
        if (b == 2) {
          const int col = offset(2) + static_cast<int>(c.node[2 * al + s]) * d;
          for (int i = 0; i < d; ++i)
            for (int j = 0; j < d; ++j) H(al * d + i, col + j) += sign * fr[i * d + j];
          continue;
        }
        const auto x = st.field(rigid::nodes, rigid::position).row(b, Depth::begin);
        const auto v = st.field(rigid::nodes, rigid::velocity).row(b, Depth::begin);
        Eigen::Vector3d r(0, 0, 0);
        for (int q = 0; q < d; ++q) r[q] = c.point[3 * al + q] - (x[q] + a * v[q]);
        for (int i = 0; i < d; ++i) {
          Eigen::Vector3d e(0, 0, 0);
          for (int q = 0; q < d; ++q) e[q] = fr[i * d + q];
          for (int q = 0; q < d; ++q) H(al * d + i, offset(b) + q) += sign * e[q];
          if (d == 2) {
            H(al * d + i, offset(b) + 2) += sign * (e[1] * r[0] - e[0] * r[1]);  // e · (ω ẑ × r)
          } else {
            const Eigen::Vector3d rxe = r.cross(e);  // e · (ω × r) = ω · (r × e)
            for (int q = 0; q < 3; ++q) H(al * d + i, offset(b) + 3 + q) += sign * rxe[q];
          }
        }
        (void)kr;
      }
    return H;
  }

  /// v_free of every unknown, from the definitions: rigid v + h g; chain
  /// v + (M + h²θ²K)⁻¹ (h(−K u + M g) − θh²K v).
  Eigen::VectorXd dense_free(const Eigen::MatrixXd& Ainv) const {
    Eigen::VectorXd vf = Eigen::VectorXd::Zero(dofs());
    const auto v = st.field(rigid::nodes, rigid::velocity).row(0, Depth::begin);
    const auto w = st.field(rigid::nodes, rigid::angular_velocity).row(0, Depth::begin);
    for (int q = 0; q < d; ++q) vf[q] = v[q] + h * ctx.gravity[q];
    for (int q = 0; q < k_rigid() - d; ++q) vf[d + q] = w[q];  // isotropic: no gyroscopic term
    const int c = offset(2), n = 3 * d;
    const Eigen::MatrixXd Linv = Ainv.block(c, c, n, n);
    const Eigen::MatrixXd K = stiffness();
    Eigen::VectorXd u(n), vc(n), g(n);
    const auto x = st.field("chain.nodes", "position").rows(0, 3, Depth::begin);
    const auto X = st.field("chain.nodes", "rest_position").rows(0, 3);
    const auto vv = st.field("chain.nodes", "velocity").rows(0, 3, Depth::begin);
    for (int j = 0; j < n; ++j) {
      u[j] = x[j] - X[j];
      vc[j] = vv[j];
      g[j] = mc * ctx.gravity[j % d];
    }
    vf.segment(c, n) = vc + Linv * (h * (-K * u + g) - theta * h * h * K * vc);
    return vf;
  }
};

void check_mixed(int d) {
  Mixed s(d);
  const ContactSides c = s.contacts();
  ContactAssembly as;
  LocalProblem P;
  as.build(s.st, s.models, c, false, P);
  EXPECT_FALSE(as.factored()) << "a chain touches contacts: no compact inverse, W is given";
  ASSERT_EQ(P.W.rows(), static_cast<Eigen::Index>(c.size() * d));
  const Eigen::MatrixXd Ainv = s.lhs_inverse();
  const Eigen::MatrixXd H = s.dense_H(c);
  const Eigen::MatrixXd W_ref = H * Ainv * H.transpose();
  const Eigen::MatrixXd W = Eigen::MatrixXd(P.W);
  const double scale = W_ref.cwiseAbs().maxCoeff();
  EXPECT_LT((W - W_ref).cwiseAbs().maxCoeff(), 1e-12 * scale) << "W\n" << W << "\nreference\n" << W_ref;
  // Contacts 0 and 1 (both ends of the chain on the floor) are coupled through the chain's
  // LHS⁻¹ only: that block is not zero.
  EXPECT_GT(W.block(0, d, d, d).cwiseAbs().maxCoeff(), 1e-6 * scale);
  // q = H v_free and u⁻ = H v⁻.
  const Eigen::VectorXd vf = s.dense_free(Ainv);
  const Eigen::VectorXd q = as.local_velocity(s.st, Velocity::free);
  EXPECT_LT((q - H * vf).cwiseAbs().maxCoeff(), 1e-12 * (1 + vf.cwiseAbs().maxCoeff()));
  // Impulses r (normal, compressive; tangential too) given back to the models: Hᵀ r into
  // their `reaction`, and their update gives v⁺ = v_free + LHS⁻¹ Hᵀ r, so that
  // H v⁺ = q + W r, the relation every solver relies on.
  const int nc = static_cast<int>(c.size());
  Eigen::VectorXd r(nc * d);
  for (int a = 0; a < nc; ++a)
    for (int i = 0; i < d; ++i) r[a * d + i] = i == 0 ? 1.0 + 0.5 * a : 0.1 * (i - 0.5 * a);
  as.store_reactions(s.st, r);
  // The generalised impulses each model received: Hᵀ r on its nodes' unknowns.
  const Eigen::VectorXd Pr = H.transpose() * r;
  const auto Pb = s.st.field(rigid::nodes, rigid::reaction).row(0);
  const auto Pc = s.st.field("chain.nodes", "reaction").rows(0, 3);
  for (int j = 0; j < s.k_rigid(); ++j) EXPECT_NEAR(Pb[j], Pr[j], 1e-12) << "ball " << j;
  for (int j = 0; j < 3 * d; ++j) EXPECT_NEAR(Pc[j], Pr[s.offset(2) + j], 1e-12) << "chain " << j;
  s.ctx.contact_impulses = true;
  for (auto* i : {s.theta_int.get(), s.chain_int.get()}) i->update_dofs(s.ctx);
  const Eigen::VectorXd v_ref = vf + Ainv * Pr;
  Eigen::VectorXd v(s.dofs());
  const auto vb = s.st.field(rigid::nodes, rigid::velocity).row(0, Depth::end);
  const auto wb = s.st.field(rigid::nodes, rigid::angular_velocity).row(0, Depth::end);
  for (int q2 = 0; q2 < d; ++q2) v[q2] = vb[q2];
  for (int q2 = 0; q2 < s.k_rigid() - d; ++q2) v[d + q2] = wb[q2];
  v.segment(s.k_rigid(), s.k_rigid()).setZero();
  const auto vc = s.st.field("chain.nodes", "velocity").rows(0, 3, Depth::end);
  for (int j = 0; j < 3 * d; ++j) v[s.offset(2) + j] = vc[j];
  // In 3D the theta integrator turns ω⁺ to the world axes at the end of the step (the
  // rotation of the step): the ball's angular part is compared in 2D only.
  if (d == 3) v.segment(d, 3) = v_ref.segment(d, 3);
  EXPECT_LT((v - v_ref).cwiseAbs().maxCoeff(), 1e-10) << v.transpose() << "\n" << v_ref.transpose();
  if (d == 2) {
    const Eigen::VectorXd u = H * v, u_ref = q + W * r;  // the relation every solver relies on
    EXPECT_LT((u - u_ref).cwiseAbs().maxCoeff(), 1e-10) << u.transpose() << "\n" << u_ref.transpose();
  }
}

}  // namespace

TEST(ContactAssembly, MixedRigidAndChain2DMatchesDenseW) { check_mixed(2); }
TEST(ContactAssembly, MixedRigidAndChain3DMatchesDenseW) { check_mixed(3); }

TEST(ContactAssembly, RigidContactsGiveTheFactoredForm) {
  // Only rigid bodies in the contacts (the ball on the floor): every moving body gives a
  // compact k × k inverse, so the problem carries H blocks and inverses, and the W built
  // from them (for solvers that read it) equals the dense one.
  for (int d : {2, 3}) {
    Mixed s(d);
    ContactSides all = s.contacts(), c;
    for (std::size_t k = 0; k < all.body.size(); ++k) {
      if (k / 2 != 3) continue;  // contact 3: ball on floor
      c.body.push_back(all.body[k]);
      c.model.push_back(all.model[k]);
      c.node.push_back(all.node[k]);
    }
    c.point.assign(all.point.begin() + 9, all.point.begin() + 12);
    c.frame.assign(all.frame.begin() + 3 * d * d, all.frame.begin() + 4 * d * d);
    ContactAssembly as;
    LocalProblem P;
    as.build(s.st, s.models, c, true, P);
    ASSERT_TRUE(as.factored());
    EXPECT_EQ(P.factor.k, d == 2 ? 3 : 6);
    EXPECT_EQ(P.factor.body[1], -1) << "the fixed floor is marked";
    const Eigen::MatrixXd H = s.dense_H(c);
    const Eigen::MatrixXd W_ref = H * s.lhs_inverse() * H.transpose();
    EXPECT_LT((Eigen::MatrixXd(P.W) - W_ref).cwiseAbs().maxCoeff(), 1e-12 * W_ref.cwiseAbs().maxCoeff());
  }
}

TEST(ContactAssembly, BallOnGroundDelassusByHand) {
  // The ball (mass m, isotropic inertia I) on the fixed floor, the point a distance R below
  // its centre at the detection configuration: W_nn = 1/m (the lever arm is along n), each
  // tangent 1/m + R²/I (rolling couples in), no coupling between the directions.
  for (int d : {2, 3}) {
    Mixed s(d);
    const double R = 0.25;
    const auto x = s.st.field(rigid::nodes, rigid::detection_position).row(0);
    ContactSides c;
    c.body = {0, 1};
    c.model = {0, 0};
    c.node = {0, 1};
    c.point = {x[0], x[1] - R, d == 3 ? x[2] : 0.0};
    const double n[3] = {0, 1, 0};
    if (d == 2) {
      for (const auto& row : local_frame_2d(n)) c.frame.insert(c.frame.end(), row.begin(), row.end());
    } else {
      for (const auto& row : local_frame_3d(n)) c.frame.insert(c.frame.end(), row.begin(), row.end());
    }
    ContactAssembly as;
    LocalProblem P;
    as.build(s.st, s.models, c, true, P);
    const Eigen::MatrixXd W(P.W);
    EXPECT_NEAR(W(0, 0), 1 / s.m, 1e-14) << d << "D";
    for (int t = 1; t < d; ++t) EXPECT_NEAR(W(t, t), 1 / s.m + R * R / s.I, 1e-13) << d << "D";
    for (int i = 0; i < d; ++i)
      for (int j = 0; j < d; ++j)
        if (i != j) EXPECT_NEAR(W(i, j), 0.0, 1e-14) << d << "D " << i << j;
  }
}
