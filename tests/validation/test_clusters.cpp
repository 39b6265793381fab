// Clusters: several contactors on one body, each at a placement (offset, rotation) in the
// body frame. The bodies are written with their origin away from the centre of mass, so
// every test also checks that the origin moves to the centre of mass (the state's position)
// while the contactors stay where the scene put them.
//
// Tolerances. Mass properties are sums of closed forms: compared to 1e-12 (rounding).
// Resting clusters: the solver runs to 1e-12 at rest, so force sums and shares are compared
// at 1e-6 W and rotations at 1e-9 rad, as in test_stacks / test_blocks. Free flight: the
// θ = 0.5 scheme is second order in rotation (tests/physics/test_rotation.cpp), so the
// drift of angular momentum and energy must fall by about 4 when h halves; the centre of
// mass moves exactly uniformly (no force: the update is exact to rounding).
#include <array>
#include <cmath>
#include <sstream>

#include "run_scene.hpp"

using namespace moreau_test;

namespace {

constexpr double g = 9.81, rho = 1000;

/// Sum over the contacts of the last frame of the force component k.
double force_sum(const SceneRun& run, const std::string& frame, int dim, int k) {
  const auto force = run.at(frame, "contacts/force");
  double s = 0;
  for (std::size_t c = 0; c < force.size() / dim; ++c) s += force[c * dim + k];
  return s;
}

using Mat = std::array<double, 9>;

/// Inertia about the centre of mass of point-placed parts (mass, centre, own inertia):
/// Σ [I_i + m_i (|d|² E − d dᵀ)], d from the common centre. Also returns that centre.
struct Part {
  double m;
  std::array<double, 3> c;
  Mat I;
};
Mat cluster_inertia(const std::vector<Part>& parts, std::array<double, 3>& com, double& mass) {
  mass = 0;
  com = {0, 0, 0};
  for (const auto& p : parts) {
    mass += p.m;
    for (int k = 0; k < 3; ++k) com[k] += p.m * p.c[k];
  }
  for (double& x : com) x /= mass;
  Mat I{};
  for (const auto& p : parts) {
    const double d[3] = {p.c[0] - com[0], p.c[1] - com[1], p.c[2] - com[2]};
    const double d2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) I[3 * i + j] += p.I[3 * i + j] + p.m * ((i == j ? d2 : 0.0) - d[i] * d[j]);
  }
  return I;
}

Mat diag(double a, double b, double c) { return {a, 0, 0, 0, b, 0, 0, 0, c}; }
Part sphere(double r, std::array<double, 3> c) {
  const double m = rho * 4.0 / 3.0 * M_PI * r * r * r;
  const double i = 0.4 * m * r * r;
  return {m, c, diag(i, i, i)};
}

void quat_matrix(const double* q, double* R) {
  const double w = q[0], x = q[1], y = q[2], z = q[3];
  const double m[9] = {1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y),
                       2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x),
                       2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)};
  for (int k = 0; k < 9; ++k) R[k] = m[k];
}

}  // namespace

TEST(Clusters, TwoDisksRestOnAFloorEachCarryingHalfTheWeight) {
  // Disks of radius 0.1 at x = −0.3 and 0.3, the body origin written at the left one.
  // Mass 2ρπR², inertia 2(ρπR⁴/2 + ρπR² d²) with d = 0.3.
  const double R = 0.1, d = 0.3, md = rho * M_PI * R * R, W = 2 * md * g;
  SceneRun run = run_scene("cluster_two_disks", R"({"format": "moreau-scene/1", "dimension": 2,
  "time": {"step": 1e-3, "duration": 1}, "gravity": [0, -9.81], "materials": {"m": {"density": 1000}},
  "laws": {"rough": {"type": "coulomb", "friction": 0.3}},
  "interactions": [{"groups": ["rod", "floor"], "law": "rough"}],
  "solver": {"type": "nlgs", "tolerance": 1e-12, "max_iterations": 1000}, "output": {"every": 100},
  "bodies": [{"name": "floor", "fixed": true, "position": [0, -0.01], "contactors": [{"shape": "segment", "length": 4, "thickness": 0.02, "group": "floor"}]},
             {"name": "pair", "material": "m", "position": [-0.3, 0.1],
              "contactors": [{"shape": "disk", "radius": 0.1, "group": "rod"},
                             {"shape": "disk", "radius": 0.1, "offset": [0.6, 0], "group": "rod"}]}]})");
  const auto mass = read_doubles(run.file, "/bodies/mass"), inertia = read_doubles(run.file, "/bodies/inertia");
  const double I = 2 * (md * R * R / 2 + md * d * d);
  std::printf("two disks: mass %.12g (2 rho pi R^2 = %.12g), inertia %.12g (2(I_disk + m d^2) = %.12g)\n", mass[1],
              2 * md, inertia[1], I);
  EXPECT_NEAR(mass[1], 2 * md, 1e-12 * md);
  EXPECT_NEAR(inertia[1], I, 1e-12 * I);
  // The origin moved to the centre of mass; the placements were re-expressed about it.
  const auto x0 = run.at(run.frames.front(), "position");
  EXPECT_NEAR(x0[2], 0.0, 1e-15);
  EXPECT_NEAR(x0[3], 0.1, 1e-15);
  const auto offsets = read_doubles(run.file, "/contactors/offset");
  ASSERT_EQ(offsets.size(), 3u * 2);  // the floor's, then the pair's two
  EXPECT_NEAR(offsets[2], -0.3, 1e-15);
  EXPECT_NEAR(offsets[4], 0.3, 1e-15);

  double worst_angle = 0;
  for (const auto& f : run.frames) worst_angle = std::max(worst_angle, std::fabs(run.at(f, "angle")[1]));
  const auto& last = run.frames.back();
  const auto point = run.at(last, "contacts/point"), force = run.at(last, "contacts/force");
  ASSERT_EQ(force.size(), 2u * 2) << "one contact under each disk";
  for (int c = 0; c < 2; ++c) {
    std::printf("  contact at x = %+.9f: normal force %.9f N (W/2 = %.9f), tangential %+.6f N\n", point[2 * c],
                force[2 * c + 1], W / 2, force[2 * c]);
    EXPECT_NEAR(std::fabs(point[2 * c]), d, 1e-9);
    EXPECT_NEAR(force[2 * c + 1], W / 2, 1e-6 * W);
    EXPECT_LE(std::fabs(force[2 * c]), 0.3 * force[2 * c + 1] * (1 + 1e-9)) << "inside the Coulomb cone";
  }
  // Two sticking contacts on one rigid body are hyperstatic: any self-equilibrated pair of
  // tangential forces inside the cones is a solution (NLGS keeps the one its first sweeps
  // build), so only their sum is determined, and the normal forces (moments about the
  // centre of mass: the pair's moment cancels).
  EXPECT_NEAR(force[0] + force[2], 0.0, 1e-6 * W);
  std::printf("  largest |angle| %.3e rad\n", worst_angle);
  EXPECT_LT(worst_angle, 1e-9);
}

TEST(Clusters, UnequalDumbbellSharesItsWeightByTheLeverRule) {
  // Spheres R1 = 0.1 (at the written origin) and R2 = 0.05 (offset [0.4, 0, −0.05]) both
  // touch the plane z = 0. Moments about the centre of mass: F1 (xc − x1) = F2 (x2 − xc).
  const double R1 = 0.1, R2 = 0.05;
  const Part s1 = sphere(R1, {0, 0, 0}), s2 = sphere(R2, {0.4, 0, -0.05});
  std::array<double, 3> c;
  double m;
  cluster_inertia({s1, s2}, c, m);
  const double W = m * g, x1 = 0.1, x2 = 0.5, xc = 0.1 + c[0];
  const double F1 = W * (x2 - xc) / (x2 - x1), F2 = W - F1;
  SceneRun run = run_scene("cluster_dumbbell", R"({"format": "moreau-scene/1", "dimension": 3,
  "time": {"step": 1e-3, "duration": 1}, "gravity": [0, 0, -9.81], "materials": {"m": {"density": 1000}},
  "laws": {"rough": {"type": "coulomb", "friction": 0.3}},
  "interactions": [{"groups": ["bell", "floor"], "law": "rough"}],
  "solver": {"type": "nlgs", "tolerance": 1e-12, "max_iterations": 1000}, "output": {"every": 100},
  "bodies": [{"name": "floor", "fixed": true, "position": [0, 0, 0], "contactors": [{"shape": "plane", "group": "floor"}]},
             {"name": "bell", "material": "m", "position": [0.1, 0.2, 0.1],
              "contactors": [{"shape": "sphere", "radius": 0.1, "group": "bell"},
                             {"shape": "sphere", "radius": 0.05, "offset": [0.4, 0, -0.05], "group": "bell"}]}]})");
  const auto x0 = run.at(run.frames.front(), "position");
  EXPECT_NEAR(x0[3], 0.1 + c[0], 1e-15);
  EXPECT_NEAR(x0[5], 0.1 + c[2], 1e-15);
  const auto& last = run.frames.back();
  const auto point = run.at(last, "contacts/point"), force = run.at(last, "contacts/force");
  ASSERT_EQ(force.size(), 2u * 3) << "one contact under each sphere";
  for (int k = 0; k < 2; ++k) {
    const bool big = std::fabs(point[3 * k] - x1) < 1e-9;
    std::printf("dumbbell: contact at x = %.9f: normal force %.9f N (lever rule %.9f)\n", point[3 * k],
                force[3 * k + 2], big ? F1 : F2);
    EXPECT_NEAR(point[3 * k], big ? x1 : x2, 1e-9);
    EXPECT_NEAR(force[3 * k + 2], big ? F1 : F2, 1e-6 * W);
  }
  double worst = 0;
  for (const auto& f : run.frames) {
    const auto q = run.at(f, "orientation");
    worst = std::max({worst, std::fabs(q[5]), std::fabs(q[6]), std::fabs(q[7])});
  }
  std::printf("  largest rotation (quaternion vector part) %.3e\n", worst);
  EXPECT_LT(worst, 1e-9);
}

TEST(Clusters, MassPropertiesOfARotatedBoxAndTwoSpheres) {
  // A 0.2 × 0.1 × 0.05 box turned 90° about z (so 0.1 × 0.2 × 0.05 in the body axes), and
  // two spheres off the axes: the tensor has products of inertia.
  const double s = std::sqrt(0.5);
  const double mb = rho * 0.2 * 0.1 * 0.05;
  const Part box{mb, {0.05, 0, 0}, diag(mb * (0.2 * 0.2 + 0.05 * 0.05) / 12, mb * (0.1 * 0.1 + 0.05 * 0.05) / 12,
                                        mb * (0.1 * 0.1 + 0.2 * 0.2) / 12)};
  const Part a = sphere(0.05, {0.2, 0.1, 0}), b = sphere(0.04, {0, -0.1, 0.15});
  std::array<double, 3> c;
  double m;
  const Mat I = cluster_inertia({box, a, b}, c, m);
  std::ostringstream sc;
  sc.precision(17);
  sc << R"({"format": "moreau-scene/1", "dimension": 3, "time": {"step": 1e-3, "duration": 1e-3},
  "materials": {"m": {"density": 1000}},
  "bodies": [{"name": "cluster", "material": "m", "position": [1, 2, 3], "contactors": [
    {"shape": "box", "size": [0.2, 0.1, 0.05], "offset": [0.05, 0, 0], "orientation": [)" << s << ", 0, 0, " << s << R"(]},
    {"shape": "sphere", "radius": 0.05, "offset": [0.2, 0.1, 0]},
    {"shape": "sphere", "radius": 0.04, "offset": [0, -0.1, 0.15]}]}]})";
  SceneRun run = run_scene("cluster_mass", sc.str());
  const auto mass = read_doubles(run.file, "/bodies/mass"), in = read_doubles(run.file, "/bodies/inertia");
  const double expected[6] = {I[0], I[4], I[8], I[1], I[2], I[5]};
  std::printf("cluster: mass %.12g (expected %.12g); inertia xx yy zz xy xz yz:\n", mass[0], m);
  EXPECT_NEAR(mass[0], m, 1e-12 * m);
  for (int k = 0; k < 6; ++k) {
    std::printf("  %+.12e  (expected %+.12e)\n", in[k], expected[k]);
    EXPECT_NEAR(in[k], expected[k], 1e-12 * I[8]);
  }
  EXPECT_GT(std::fabs(in[3]), 1e-2 * in[0]) << "the test needs products of inertia";
  const auto x0 = run.at(run.frames.front(), "position");
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(x0[k], 1 + k + c[k], 1e-14);
  const auto off = read_doubles(run.file, "/contactors/offset"), q = read_doubles(run.file, "/contactors/orientation");
  const double written[3][3] = {{0.05, 0, 0}, {0.2, 0.1, 0}, {0, -0.1, 0.15}};
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(off[3 * i + k], written[i][k] - c[k], 1e-15);
  EXPECT_NEAR(q[0], s, 1e-15);
  EXPECT_NEAR(q[3], s, 1e-15);
}

namespace {

struct FlightDrift {
  double momentum = 0, energy = 0, com_velocity = 0;
};

/// Three unequal spheres spinning in free flight (no gravity) for 2 s at step h.
FlightDrift spinning_cluster(double h, std::array<double, 3>& com) {
  const Part a = sphere(0.1, {0, 0, 0}), b = sphere(0.07, {0.3, 0.05, 0}), c = sphere(0.05, {0.05, 0.25, 0.2});
  double m;
  cluster_inertia({a, b, c}, com, m);
  std::ostringstream sc;
  sc << R"({"format": "moreau-scene/1", "dimension": 3, "time": {"step": )" << h << R"(, "duration": 2},
  "materials": {"m": {"density": 1000}}, "output": {"every": )" << std::lround(0.01 / h) << R"(},
  "bodies": [{"name": "spinner", "material": "m", "position": [0, 0, 0], "angular_velocity": [1, 2, 3], "contactors": [
    {"shape": "sphere", "radius": 0.1}, {"shape": "sphere", "radius": 0.07, "offset": [0.3, 0.05, 0]},
    {"shape": "sphere", "radius": 0.05, "offset": [0.05, 0.25, 0.2]}]}]})";
  SceneRun run = run_scene(h > 1.5e-3 ? "cluster_spin_coarse" : "cluster_spin_fine", sc.str());
  const auto in = read_doubles(run.file, "/bodies/inertia");
  const double Ib[9] = {in[0], in[3], in[4], in[3], in[1], in[5], in[4], in[5], in[2]};
  // The written origin is at rest, so the centre of mass moves at ω × c (c from it).
  const double w0[3] = {1, 2, 3};
  const double vc[3] = {w0[1] * com[2] - w0[2] * com[1], w0[2] * com[0] - w0[0] * com[2], w0[0] * com[1] - w0[1] * com[0]};
  auto momentum_energy = [&](const std::string& f, double L[3], double& E) {
    const auto q = run.at(f, "orientation"), w = run.at(f, "angular_velocity");
    double R[9], W[3], IW[3];
    quat_matrix(q.data(), R);
    for (int i = 0; i < 3; ++i) W[i] = R[i] * w[0] + R[3 + i] * w[1] + R[6 + i] * w[2];  // body frame
    for (int i = 0; i < 3; ++i) IW[i] = Ib[3 * i] * W[0] + Ib[3 * i + 1] * W[1] + Ib[3 * i + 2] * W[2];
    for (int i = 0; i < 3; ++i) L[i] = R[3 * i] * IW[0] + R[3 * i + 1] * IW[1] + R[3 * i + 2] * IW[2];
    E = 0.5 * (W[0] * IW[0] + W[1] * IW[1] + W[2] * IW[2]);
  };
  double L0[3], E0;
  momentum_energy(run.frames.front(), L0, E0);
  const double n0 = std::sqrt(L0[0] * L0[0] + L0[1] * L0[1] + L0[2] * L0[2]);
  FlightDrift d;
  for (const auto& f : run.frames) {
    double L[3], E;
    momentum_energy(f, L, E);
    d.momentum = std::max(d.momentum, std::hypot(L[0] - L0[0], L[1] - L0[1], L[2] - L0[2]) / n0);
    d.energy = std::max(d.energy, std::fabs(E - E0) / E0);
    const auto v = run.at(f, "velocity");
    d.com_velocity = std::max(d.com_velocity, std::hypot(v[0] - vc[0], v[1] - vc[1], v[2] - vc[2]));
  }
  return d;
}

}  // namespace

TEST(Clusters, SpinningThreeSphereClusterConservesMomentumAndEnergyToSecondOrder) {
  std::array<double, 3> c;
  const FlightDrift a = spinning_cluster(2e-3, c), b = spinning_cluster(1e-3, c);
  std::printf("spinning 3-sphere cluster, 2 s: h = 2e-3: |dL|/|L| %.3e, |dE|/E %.3e; h = 1e-3: %.3e, %.3e\n",
              a.momentum, a.energy, b.momentum, b.energy);
  const double pL = std::log2(a.momentum / b.momentum), pE = std::log2(a.energy / b.energy);
  std::printf("  orders: momentum %.2f, energy %.2f; centre-of-mass velocity error %.1e m/s\n", pL, pE,
              std::max(a.com_velocity, b.com_velocity));
  EXPECT_GT(pL, 1.8);
  EXPECT_GT(pE, 1.8);
  EXPECT_LT(b.momentum, 1e-3);
  EXPECT_LT(b.energy, 1e-3);
  EXPECT_LT(std::max(a.com_velocity, b.com_velocity), 1e-12);
}

TEST(Clusters, RodOfDisksLandsFlatOnBothEnds) {
  // Five disks of radius 0.1 in a row (a rod 1 m long), written with the origin at the first
  // one, dropped flat from 0.2 m: it lands on all of them, both ends touching, no rotation.
  const double R = 0.1, W = 5 * rho * M_PI * R * R * g;
  std::ostringstream sc;
  sc << R"({"format": "moreau-scene/1", "dimension": 2,
  "time": {"step": 1e-3, "duration": 1}, "gravity": [0, -9.81], "materials": {"m": {"density": 1000}},
  "laws": {"rough": {"type": "coulomb", "friction": 0.3}},
  "interactions": [{"groups": ["rod", "floor"], "law": "rough"}],
  "solver": {"type": "nlgs", "tolerance": 1e-12, "max_iterations": 2000}, "output": {"every": 50},
  "bodies": [{"name": "floor", "fixed": true, "position": [0, -0.01], "contactors": [{"shape": "segment", "length": 4, "thickness": 0.02, "group": "floor"}]},
             {"name": "rod", "material": "m", "position": [-0.4, 0.3], "contactors": [)";
  for (int k = 0; k < 5; ++k) sc << (k ? ", " : "") << R"({"shape": "disk", "radius": 0.1, "offset": [)" << 0.2 * k << R"(, 0], "group": "rod"})";
  sc << "]}]}";
  SceneRun run = run_scene("cluster_rod", sc.str());
  double worst_angle = 0;
  for (const auto& f : run.frames) worst_angle = std::max(worst_angle, std::fabs(run.at(f, "angle")[1]));
  const auto& last = run.frames.back();
  const auto point = run.at(last, "contacts/point"), gap = run.at(last, "contacts/gap");
  bool left = false, right = false;
  for (std::size_t c = 0; c < gap.size(); ++c) {
    if (std::fabs(gap[c]) > 1e-6) continue;
    left = left || std::fabs(point[2 * c] + 0.4) < 1e-9;
    right = right || std::fabs(point[2 * c] - 0.4) < 1e-9;
  }
  const double fy = force_sum(run, last, 2, 1), y = run.at(last, "position")[3];
  std::printf("rod of 5 disks: %zu contacts, both ends touching %d %d, vertical force %.9f N (W = %.9f), centre at "
              "y = %.9f, largest |angle| %.3e rad\n", gap.size(), left, right, fy, W, y, worst_angle);
  EXPECT_TRUE(left && right);
  EXPECT_NEAR(fy, W, 1e-6 * W);
  EXPECT_NEAR(y, R, 1e-6);
  EXPECT_LT(worst_angle, 1e-9);
}
