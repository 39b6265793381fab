// Regular arrays in a box (Dumont, Fortin & Ouafik 2010, §5.1, fig. 6): the normal forces
// of the run, once at rest, equal the analytic statics to the solver's tolerance (1e-10,
// relative to the weights: compared to 1e-8 of a grain's weight).
//  - rectangular (square array of frictionless disks between walls): each column carries
//    the weight above it; horizontal contacts carry nothing;
//  - triangular (rows resting in the hollows of the row below, on a row of fixed disks):
//    every disk has exactly two supports below (two disks, or a disk and a wall), so the
//    statics are determinate, solved from the top row down;
//  - cannonball, 3D with friction: the tetrahedral stack (3 + 1 spheres) is determinate:
//    N = mg/3 on each upper contact, mg + N on the floor, and the friction that keeps each
//    base sphere from rolling, t = N cos β / (1 + sin β); the square pyramid (4 + 1, the
//    configs/cannonball_3d.json scene) is hyperstatic (a four-legged stool: how the top
//    sphere shares its weight between the diagonals is not determined), and its
//    determinate relations are checked: Σ N = mg, floor = mg + N_i, t_i = N_i cos β/(1 + sin β).
#include <cmath>

#include "analysis_run.hpp"

using namespace moreau_test;

namespace {

/// Normal forces of the statics, solved from the top down: each moving body's load (its
/// weight and the forces of the bodies above) is carried by its other contacts, with the
/// least-norm split when there are more than the dimension (horizontal contacts then carry
/// nothing, as by symmetry).
std::vector<double> statics(const SceneRun& run, int d) {
  const std::string fr = run.last();
  const auto x = run.at(fr, "position");
  const auto m = run.header("/bodies/mass");
  const auto fixed = run.header("/bodies/fixed");
  const auto B = run.at(fr, "contacts/bodies");
  const auto N = run.at(fr, "contacts/normal");
  const std::size_t nb = m.size(), nc = B.size() / 2;
  std::vector<double> f(nc, NAN);
  std::vector<std::size_t> order;
  for (std::size_t b = 0; b < nb; ++b)
    if (fixed[b] == 0) order.push_back(b);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return x[a * d + d - 1] > x[b * d + d - 1]; });
  for (std::size_t b : order) {
    std::vector<double> load(d, 0.0);
    load[d - 1] = -9.81 * m[b];
    std::vector<std::pair<std::size_t, std::vector<double>>> sup;
    for (std::size_t c = 0; c < nc; ++c) {
      const std::size_t i = static_cast<std::size_t>(B[2 * c]), j = static_cast<std::size_t>(B[2 * c + 1]);
      if (i != b && j != b) continue;
      const std::size_t o = i == b ? j : i;
      std::vector<double> n(d);
      for (int k = 0; k < d; ++k) n[k] = N[c * d + k] * (i == b ? 1.0 : -1.0);  // into b
      if (fixed[o] == 0 && x[o * d + d - 1] > x[b * d + d - 1] + 1e-9) {
        EXPECT_FALSE(std::isnan(f[c]));
        for (int k = 0; k < d; ++k) load[k] += f[c] * n[k];
      } else {
        sup.emplace_back(c, n);
      }
    }
    // Least-norm N with Σ N_s n_s = −load: N = Aᵀ (A Aᵀ)⁻¹ (−load), A = [n_s] (d × k).
    double G[9] = {0}, rhs[3] = {0, 0, 0}, y[3] = {0, 0, 0};
    for (const auto& s : sup)
      for (int p = 0; p < d; ++p)
        for (int q = 0; q < d; ++q) G[p * 3 + q] += s.second[p] * s.second[q];
    for (int k = 0; k < d; ++k) rhs[k] = -load[k];
    if (d == 2) {
      const double det = G[0] * G[4] - G[1] * G[3];
      y[0] = (rhs[0] * G[4] - G[1] * rhs[1]) / det;
      y[1] = (G[0] * rhs[1] - G[3] * rhs[0]) / det;
    } else {
      ADD_FAILURE() << "3D statics: use the closed forms";
    }
    for (const auto& s : sup) {
      double v = 0;
      for (int k = 0; k < d; ++k) v += s.second[k] * y[k];
      f[s.first] = v;
    }
  }
  return f;
}

void expect_statics(const std::string& config, std::size_t contacts) {
  json scene = read_config(config);
  SceneRun run = run_json(config.substr(0, config.find('.')), scene);
  ASSERT_FALSE(run.frames.empty());
  const auto fn = run.at(run.last(), "contacts/normal_force");
  ASSERT_EQ(fn.size(), contacts) << "the array's contacts";
  const auto f = statics(run, 2);
  const auto m = run.header("/bodies/mass");
  const double W = 9.81 * *std::max_element(m.begin(), m.end());
  double worst = 0;
  for (std::size_t c = 0; c < fn.size(); ++c) {
    ASSERT_FALSE(std::isnan(f[c])) << "contact " << c << " has no statics";
    EXPECT_GE(f[c], -1e-12 * W) << "contact " << c << ": the statics need tension";
    worst = std::max(worst, std::fabs(fn[c] - f[c]) / W);
  }
  std::printf("%s: %zu contacts, largest |f_n - statics| = %.2e of a grain's weight\n", config.c_str(), fn.size(), worst);
  EXPECT_LT(worst, 1e-8);
}

}  // namespace

TEST(Arrays, RectangularNormalForcesAreTheStatics) {
  // 4 columns of 5 disks: 4 floor + 16 vertical + 15 horizontal + 10 wall contacts.
  expect_statics("array_rectangular_2d.json", 45);
}

TEST(Arrays, TriangularNormalForcesAreTheStatics) {
  // 5 moving rows on a fixed row of 5: 8 + 2·(4+4+4) supports + 2 per n-row at the walls.
  expect_statics("array_triangular_2d.json", 44);
}

// The fabric of the rectangular array (4 columns of 5 frictionless disks, radius r, on a
// floor between walls) is known exactly: the 20 vertical contacts (4 on the floor) carry
// the columns' weights k mg (k = 1..5), the 25 horizontal and wall contacts nothing.
// Coordination (2·16 + 4)/20 = 1.8; with the rattler rule (fewer than 2 contacts) every
// column unravels from its top: no body is left; fabric tensor diag(0, 1); mean normal
// force 3 mg; strong network f_n > 3 mg: 2/5 of the contacts, (4 + 5)/15 of the force (the
// k = 3 contacts are on the threshold: with them 3/5 and 12/15);
// solid fraction of the whole sample's box (the disks' extents, 8r × 10r): π/4.
TEST(Arrays, FabricOfTheRectangularArray) {
  SceneRun run = run_json("rectangular_fabric", read_config("array_rectangular_2d.json"));
  ASSERT_FALSE(run.frames.empty());
  const std::string fr = run.last();
  const auto m = run.header("/bodies/mass");
  const double W = 9.81 * *std::max_element(m.begin(), m.end());
  auto at = [&](const std::string& name) { return run.scalar(fr, "analyses/fabric/" + name); };
  EXPECT_EQ(at("bodies"), 20);
  EXPECT_EQ(at("contacts"), 20);
  EXPECT_NEAR(at("coordination"), 1.8, 1e-15);
  EXPECT_EQ(at("coordination_no_rattlers"), 0);
  EXPECT_EQ(at("rattler_fraction"), 1);
  const auto F = run.at(fr, "analyses/fabric/fabric");
  ASSERT_EQ(F.size(), 4u);
  EXPECT_NEAR(F[0], 0, 1e-15);
  EXPECT_NEAR(F[1], 0, 1e-15);
  EXPECT_NEAR(F[3], 1, 1e-15);
  EXPECT_NEAR(at("mean_normal_force"), 3 * W, 1e-8 * W);
  // The 4 contacts at k = 3 carry exactly <f_n>: on the threshold, rounding decides. Ties
  // weak: 2/5 of the contacts and 9/15 of the force; ties strong: 3/5 and 12/15.
  const bool ties_strong = at("strong_share") > 0.5;
  EXPECT_NEAR(at("strong_share"), ties_strong ? 0.6 : 0.4, 1e-15);
  EXPECT_NEAR(at("strong_force_share"), ties_strong ? 0.8 : 0.6, 1e-8);
  EXPECT_NEAR(at("solid_fraction"), M_PI / 4, 1e-12);
  const auto pdf = run.at(fr, "analyses/fabric/pdf");
  const auto edges = run.at(fr, "analyses/fabric/pdf_edges");
  double total = 0;
  for (std::size_t k = 0; k < pdf.size(); ++k) total += pdf[k] * (edges[k + 1] - edges[k]);
  EXPECT_NEAR(total, 1, 1e-12);
  EXPECT_EQ(at("pdf_beyond"), 0);
  std::printf("rectangular array fabric: z = %.4f, F_yy = %.4f, <f_n> = %.6f mg, strong %.3f / %.6f, solid fraction %.6f "
              "(pi/4 = %.6f)\n",
              at("coordination"), F[3], at("mean_normal_force") / W, at("strong_share"), at("strong_force_share"),
              at("solid_fraction"), M_PI / 4);
}

namespace {

/// Normal force, tangential magnitude and the two bodies of each contact of the last frame.
struct Contacts {
  std::vector<int> a, b;
  std::vector<double> fn, ft;
};
Contacts contacts_of(const SceneRun& run, int d) {
  Contacts c;
  const auto B = run.at(run.last(), "contacts/bodies");
  const auto imp = run.at(run.last(), "contacts/impulse");
  const double h = 1e-3;
  for (std::size_t i = 0; i < B.size() / 2; ++i) {
    c.a.push_back(static_cast<int>(B[2 * i]));
    c.b.push_back(static_cast<int>(B[2 * i + 1]));
    c.fn.push_back(imp[i * d] / h);
    double t = 0;
    for (int k = 1; k < d; ++k) t += imp[i * d + k] * imp[i * d + k];
    c.ft.push_back(std::sqrt(t) / h);
  }
  return c;
}

}  // namespace

TEST(Arrays, TetrahedralCannonballWithFriction) {
  // Three spheres on the floor, apart by 1 %, one on top: elevation β of the upper contacts
  // from cos β = (s/√3)/(2R).
  const double R = 0.05, s = 2 * R * 1.01, rho = 7800;
  const double m = rho * 4.0 / 3.0 * M_PI * R * R * R, W = m * 9.81;
  const double c = s / std::sqrt(3.0) / (2 * R), sb = std::sqrt(1 - c * c);
  const double h = s * std::sqrt(3.0) / 2;
  json scene = json::parse(R"({"format": "moreau-scene/1", "dimension": 3,
    "time": {"step": 1e-3, "duration": 0.02}, "gravity": [0, 0, -9.81],
    "materials": {"iron": {"density": 7800}}, "laws": {"rough": {"type": "coulomb", "friction": 0.5}},
    "bodies": [{"name": "floor", "fixed": true, "position": [0, 0, 0], "contactors": [{"shape": "plane", "group": "wall"}]}],
    "interactions": [{"groups": ["ball", "ball"], "law": "rough"}, {"groups": ["ball", "wall"], "law": "rough"}],
    "solver": {"type": "nlgs", "tolerance": 1e-10, "max_iterations": 20000},
    "output": {"every": 10}})");
  const double base[3][2] = {{0, 0}, {s, 0}, {s / 2, h}};
  for (int i = 0; i < 3; ++i)
    scene["bodies"].push_back({{"name", "b" + std::to_string(i)}, {"material", "iron"},
                               {"position", {base[i][0], base[i][1], R}},
                               {"contactors", {{{"shape", "sphere"}, {"radius", R}, {"group", "ball"}}}}});
  scene["bodies"].push_back({{"name", "top"}, {"material", "iron"}, {"position", {s / 2, h / 3, R + 2 * R * sb}},
                             {"contactors", {{{"shape", "sphere"}, {"radius", R}, {"group", "ball"}}}}});
  SceneRun run = run_json("tetrahedral", scene);
  ASSERT_FALSE(run.frames.empty());
  const Contacts k = contacts_of(run, 3);
  ASSERT_EQ(k.fn.size(), 6u);
  const double t = W / 3 * c / (1 + sb);
  double worst = 0;
  for (std::size_t i = 0; i < k.fn.size(); ++i) {
    const bool floor = k.a[i] == 0 || k.b[i] == 0;
    worst = std::max({worst, std::fabs(k.fn[i] - (floor ? 4 * W / 3 : W / 3)) / W, std::fabs(k.ft[i] - t) / W});
  }
  std::printf("tetrahedral cannonball: N = mg/3 above, 4mg/3 on the floor, friction %.4f mg: worst error %.2e mg\n", t / W,
              worst);
  EXPECT_LT(worst, 1e-8);
}

TEST(Arrays, SquareCannonballDeterminateRelations) {
  json scene = read_config("cannonball_3d.json");
  SceneRun run = run_json("cannonball", scene);
  ASSERT_FALSE(run.frames.empty());
  const Contacts k = contacts_of(run, 3);
  ASSERT_EQ(k.fn.size(), 8u);
  const auto m = run.header("/bodies/mass");
  const double W = 9.81 * m.back();
  const double R = 0.05, s = 2 * R * 1.01, c = s / std::sqrt(2.0) / (2 * R), sb = std::sqrt(1 - c * c);
  // The base spheres are bodies 5..8 (after the five walls), the top one is 9.
  std::vector<double> upper(4, NAN), upper_t(4, NAN), floor(4, NAN), floor_t(4, NAN);
  for (std::size_t i = 0; i < k.fn.size(); ++i) {
    const int lo = std::min(k.a[i], k.b[i]), hi = std::max(k.a[i], k.b[i]);
    if (hi == 9) upper[lo - 5] = k.fn[i], upper_t[lo - 5] = k.ft[i];
    else floor[hi - 5] = k.fn[i], floor_t[hi - 5] = k.ft[i];
  }
  double sum = 0, worst = 0;
  for (int i = 0; i < 4; ++i) {
    sum += upper[i];
    worst = std::max({worst, std::fabs(floor[i] - (W + upper[i])) / W, std::fabs(upper_t[i] - upper[i] * c / (1 + sb)) / W,
                      std::fabs(floor_t[i] - upper_t[i]) / W});
  }
  // Diagonal pairs (lattice order (0,0), (1,0), (0,1), (1,1)) share alike.
  worst = std::max({worst, std::fabs(sum - W) / W, std::fabs(upper[0] - upper[3]) / W, std::fabs(upper[1] - upper[2]) / W});
  std::printf("square cannonball: upper normal forces %.4f %.4f %.4f %.4f mg (sum 1), worst error %.2e mg\n", upper[0] / W,
              upper[1] / W, upper[2] / W, upper[3] / W, worst);
  EXPECT_LT(worst, 1e-8);
}

// The analyses of the same pile against its determinate statics (tolerance: the solver's
// 1e-10, compared at 1e-8 of the pile's weight or of its stress scale):
//  - walls: the force on the floor is the five weights, 5mg, straight down;
//  - polarization: all 8 contacts closed and sticking (t/N = cos β/(1 + sin β) = 0.41 <
//    μ = 0.5); the upper contacts' mean mobilisation is that ratio over μ, whatever the
//    hyperstatic split; the floor's is Σ_i t_i / (μ N_floor,i) / 4 from the contacts;
//  - stress of the whole pile (V the box around it): Σ_zz V = −mg Σ_p z_p (the floor's
//    contacts are at z = 0), Σ_xx V = Σ_yy V = −(s/(2√2)) Σ_i t_i = −(s/(2√2)) mg cos β/(1 +
//    sin β) (the floor's friction on the base spheres, at ±s/2, pointing to the axis), and
//    Σ symmetric.
TEST(Arrays, AnalysesOfTheSquareCannonball) {
  SceneRun run = run_json("cannonball_analyses", read_config("cannonball_3d.json"));
  ASSERT_FALSE(run.frames.empty());
  const std::string fr = run.last();
  const auto m = run.header("/bodies/mass");
  const double W = 9.81 * m.back(), mu = 0.5;
  const double R = 0.05, s = 2 * R * 1.01, c = s / std::sqrt(2.0) / (2 * R), sb = std::sqrt(1 - c * c);
  const double ratio = c / (1 + sb);

  const auto floor = run.at(fr, "analyses/walls/force");
  ASSERT_EQ(floor.size(), 3u);
  EXPECT_NEAR(floor[2], -5 * W, 1e-8 * W);
  EXPECT_NEAR(floor[0], 0, 1e-8 * W);
  EXPECT_NEAR(floor[1], 0, 1e-8 * W);

  // Pairs in the scene's order: ball-ball, ball-wall; columns open, sticking, sliding, moving, total.
  const auto counts = run.at(fr, "analyses/polarization/counts");
  const auto mob = run.at(fr, "analyses/polarization/mobilisation_mean");
  ASSERT_EQ(counts.size(), 10u);
  const std::vector<double> expect_counts{0, 4, 0, 0, 4, 0, 4, 0, 0, 4};
  EXPECT_EQ(counts, expect_counts);
  EXPECT_NEAR(mob[0], ratio / mu, 1e-8);
  const Contacts k = contacts_of(run, 3);
  double floor_mob = 0;
  for (std::size_t i = 0; i < k.fn.size(); ++i)
    if (std::max(k.a[i], k.b[i]) != 9) floor_mob += k.ft[i] / (mu * k.fn[i]) / 4;
  EXPECT_NEAR(mob[1], floor_mob, 1e-12);

  const auto S = run.at(fr, "analyses/stress/total");
  const double V = run.scalar(fr, "analyses/stress/volume");
  const auto x = run.at(fr, "position");
  double zsum = 0;
  for (std::size_t b = 5; b < 10; ++b) zsum += x[b * 3 + 2];
  const double scale = W * zsum / V;
  const double lateral = -s / (2 * std::sqrt(2.0)) * W * ratio / V;
  std::printf("square cannonball: floor force %.1e mg from -5 mg; mobilisation above %.6f (statics %.6f), on the floor %.6f; "
              "stress zz %.6g Pa (statics %.6g), xx %.6g yy %.6g (statics %.6g), errors %.1e %.1e %.1e of |zz|, "
              "|xy - yx| %.1e\n",
              std::fabs(floor[2] + 5 * W) / W, mob[0], ratio / mu, mob[1], S[8], -scale, S[0], S[4], lateral,
              std::fabs(S[8] + scale) / scale, std::fabs(S[0] - lateral) / scale, std::fabs(S[4] - lateral) / scale,
              std::fabs(S[1] - S[3]));
  EXPECT_NEAR(S[8], -scale, 1e-8 * scale);
  EXPECT_NEAR(S[0], lateral, 1e-8 * scale);
  EXPECT_NEAR(S[4], lateral, 1e-8 * scale);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < i; ++j) EXPECT_NEAR(S[i * 3 + j], S[j * 3 + i], 1e-12 * scale);
}
