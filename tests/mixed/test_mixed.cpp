// Rigid bodies and a second modelization (tests/mixed: chains of point masses and
// springs, several nodes per body, LHS = M + h²θ²K) in one run, through `moreau run`:
// every solver on the mixed problems, momentum balance, bit-identical restart (also after
// SIGKILL), forces and hooks addressing bodies by name, and the moreau-output/2 layout.
#include <gtest/gtest.h>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <thread>

#include "cli_runner.hpp"
#include "h5_read.hpp"
#include "mixed_scenes.hpp"

namespace fs = std::filesystem;
using namespace moreau_test;

namespace {

std::string frame(long step) {
  char name[16];
  std::snprintf(name, sizeof name, "%08ld", step);
  return name;
}

/// Vertical momentum balance of every moving body from step 0 to `last` (a frame every
/// step): Σ m v_y changes by the floor's impulses minus the weight times t; the springs
/// and the ball-bead contacts are internal. Holds to rounding whatever the solver's
/// tolerance: every contact impulse acts on both its bodies, equal and opposite.
double momentum_imbalance(const std::string& out, int d, long last, double h) {
  const double g = 9.81, mc = 1.0;
  const double m_ball = read_doubles(out, "/rigid.nodes/mass")[1];  // rows: floor, ball, flyer
  auto momentum = [&](long step) {
    const auto vc = read_doubles(out, "/frames/" + frame(step) + "/chain.nodes/velocity");
    const auto vr = read_doubles(out, "/frames/" + frame(step) + "/rigid.nodes/velocity");
    double p = 0;
    for (int i = 0; i < 4; ++i) p += mc * vc[i * d + 1];
    return p + m_ball * vr[1 * d + 1];
  };
  double floor_impulse = 0;
  for (long s = 1; s <= last; ++s) {
    const std::string c = "/frames/" + frame(s) + "/contacts/";
    const auto bodies = read_doubles(out, c + "bodies");
    const auto force = read_doubles(out, c + "force");
    for (std::size_t a = 0; a < bodies.size() / 2; ++a) {
      if (bodies[2 * a] == 0) floor_impulse -= force[a * d + 1] * h;  // floor first: the opposite acts on the other
      if (bodies[2 * a + 1] == 0) floor_impulse += force[a * d + 1] * h;
    }
  }
  const double weight = (4 * mc + m_ball) * g;
  return momentum(last) - momentum(0) - (floor_impulse - weight * static_cast<double>(last) * h);
}

struct SolverCase {
  const char* name;
  const char* json;
};

}  // namespace

// Every solver solves the mixed problems (W assembled from the rigid inverse masses and
// the chain's factorised LHS, since a chain gives no compact inverse), to its tolerance,
// with the same answer.
TEST(Mixed, EverySolverSolvesTheMixedProblems) {
  const SolverCase solvers[] = {
      {"nlgs", R"({"type": "nlgs", "tolerance": 1e-9, "max_iterations": 20000})"},
      {"psor", R"({"type": "psor", "tolerance": 1e-9, "max_iterations": 50000})"},
      {"apgd", R"({"type": "apgd", "tolerance": 1e-9, "max_iterations": 50000})"},
      {"admm", R"({"type": "admm", "tolerance": 1e-9, "max_iterations": 20000})"},
      {"newton", R"({"type": "newton", "tolerance": 1e-9})"},
      {"prox", R"({"type": "prox", "tolerance": 1e-9, "max_iterations": 20000})"},
      {"auto", R"({"type": "auto", "tolerance": 1e-9})"},
  };
  for (int d : {2, 3}) {
    std::vector<double> reference;
    for (const auto& s : solvers) {
      const fs::path dir = scratch_dir(std::string("mixed_") + s.name + std::to_string(d));
      const fs::path scene = write_file(dir, "scene.json", mixed_scene(d, s.json, 0.05));
      const Result r = run_moreau({"run", scene.string(), "--quiet"}, dir);
      ASSERT_EQ(r.code, 0) << s.name << " " << d << "D: " << r.err;
      const std::string out = (dir / "out.h5").string();
      for (long step = 1; step <= 50; ++step) {
        const auto err = read_doubles(out, "/frames/" + frame(step) + "/contacts/gap");
        ASSERT_FALSE(err.empty()) << s.name << ": no contacts at step " << step;
      }
      // Converged at every step (the frame's solver error, recomputed from r).
      double worst = 0;
      for (long step = 1; step <= 50; ++step) {
        hid_t f = H5Fopen(out.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
        hid_t g = H5Gopen2(f, ("/frames/" + frame(step) + "/solver").c_str(), H5P_DEFAULT);
        hid_t a = H5Aopen(g, "error", H5P_DEFAULT);
        double e = 0;
        H5Aread(a, H5T_NATIVE_DOUBLE, &e);
        H5Aclose(a);
        H5Gclose(g);
        H5Fclose(f);
        worst = std::max(worst, e);
      }
      EXPECT_LE(worst, 1e-9) << s.name << " " << d << "D";
      EXPECT_LT(std::fabs(momentum_imbalance(out, d, 50, 0.001)), 1e-10) << s.name << " " << d << "D";
      // The same trajectory whichever solver: positions at the end agree to what the
      // tolerance allows (1e-9 relative on impulses over 50 steps of 1 ms).
      std::vector<double> x = read_doubles(out, "/frames/" + frame(50) + "/chain.nodes/position");
      const auto xb = read_doubles(out, "/frames/" + frame(50) + "/rigid.nodes/position");
      x.insert(x.end(), xb.begin(), xb.end());
      if (reference.empty()) reference = x;
      for (std::size_t i = 0; i < x.size(); ++i) EXPECT_NEAR(x[i], reference[i], 1e-8) << s.name << " " << d << "D [" << i << "]";
    }
  }
}

TEST(Mixed, RestartIsBitIdentical) {
  for (int d : {2, 3}) {
    const fs::path dir = scratch_dir("mixed_restart" + std::to_string(d));
    const fs::path scene = write_file(dir, "scene.json", mixed_scene(d, R"({"type": "auto", "tolerance": 1e-8})", 0.2, 25));
    ASSERT_EQ(run_moreau({"run", scene.string(), "--out", "full.h5", "--quiet"}, dir).code, 0);
    ASSERT_EQ(run_moreau({"run", scene.string(), "--out", "part.h5", "--steps", "100", "--quiet"}, dir).code, 0);
    const Result r = run_moreau({"run", scene.string(), "--restart", "part.h5", "--out", "rest.h5", "--quiet"}, dir);
    ASSERT_EQ(r.code, 0) << r.err;
    for (const char* p : {"chain.nodes/position", "chain.nodes/velocity", "chain.springs/tension", "rigid.nodes/position",
                          "rigid.nodes/velocity", "rigid.nodes/angular_velocity", "contacts/impulse"}) {
      const auto a = read_doubles((dir / "full.h5").string(), "/frames/00000200/" + std::string(p));
      const auto b = read_doubles((dir / "rest.h5").string(), "/frames/00000200/" + std::string(p));
      ASSERT_EQ(a.size(), b.size()) << p;
      ASSERT_FALSE(a.empty()) << p;
      for (std::size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a[i], b[i]) << d << "D " << p << "[" << i << "]";
    }
  }
}

TEST(Mixed, AfterSigkillTheFileReadsAndTheRunContinuesBitIdentically) {
  const fs::path dir = scratch_dir("mixed_kill");
  const fs::path scene = write_file(dir, "scene.json", mixed_scene(3, R"({"type": "auto", "tolerance": 1e-8})", 100.0, 1));
  const std::string path = (dir / "killed.h5").string();
  const pid_t pid = start_moreau({"run", scene.string(), "--out", path, "--quiet"}, dir);
  for (int i = 0; i < 300 && !fs::exists(dir / "killed.h5.frames" / "00000020.h5"); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  ASSERT_TRUE(kill_moreau(pid));
  const auto frames = frame_names(path);  // readable after the kill
  ASSERT_FALSE(frames.empty());
  for (const auto& f : frames)  // every listed frame complete
    for (const char* p : {"chain.nodes/position", "chain.springs/tension", "rigid.nodes/orientation", "contacts/impulse"})
      EXPECT_NO_THROW(read_doubles(path, "/frames/" + f + "/" + p)) << f << " " << p;
  const long last = std::stol(frames.back());
  const long end = last + 30;
  ASSERT_EQ(run_moreau({"run", scene.string(), "--out", "full.h5", "--quiet", "--steps", std::to_string(end)}, dir).code, 0);
  const Result r = run_moreau({"run", scene.string(), "--restart", path, "--out", "cont.h5", "--steps", "30", "--quiet"}, dir);
  ASSERT_EQ(r.code, 0) << r.err;
  for (const char* p : {"chain.nodes/position", "rigid.nodes/position", "contacts/impulse"}) {
    const auto a = read_doubles((dir / "full.h5").string(), "/frames/" + frame(end) + "/" + p);
    const auto b = read_doubles((dir / "cont.h5").string(), "/frames/" + frame(end) + "/" + p);
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a[i], b[i]) << p << "[" << i << "]";
  }
}

// A force and a hook address the flying rigid box by name; its row in rigid.nodes is not
// its body index (the chain comes before it), and the result is exact: with θ = 1/2 and a
// constant force, v(t) = (F/m + g) t and y(t) = y₀ + (F/m + g) t²/2.
TEST(Mixed, ForcesAndHooksAddressBodiesByName) {
  for (int d : {2, 3}) {
    const fs::path dir = scratch_dir("mixed_force" + std::to_string(d));
    const std::string F = d == 2 ? "[0, 29.43]" : "[0, 29.43, 0]";  // m = 2: a = 14.715 − 9.81 = 4.905 up
    const fs::path scene = write_file(
        dir, "scene.json",
        mixed_scene(d, R"({"type": "auto"})", 0.1, 10,
                    R"(, "forces": [{"type": "constant", "body": "flyer", "force": )" + F + R"(}],
  "hooks": [{"type": "stop_when", "quantity": "position", "body": "flyer", "component": 1, "above": 5.01}])"));
    const Result r = run_moreau({"run", scene.string()}, dir);
    ASSERT_EQ(r.code, 0) << r.err;
    // y = 5 + 4.905 t²/2 passes 5.01 at t = 0.0639 s: the hook stops the run after step 64.
    EXPECT_NE(r.err.find("stopped by a hook"), std::string::npos) << r.err;
    const auto frames = frame_names((dir / "out.h5").string());
    EXPECT_EQ(frames.back(), frame(64));
    const auto x = read_doubles((dir / "out.h5").string(), "/frames/" + frame(60) + "/rigid.nodes/position");
    const auto v = read_doubles((dir / "out.h5").string(), "/frames/" + frame(60) + "/rigid.nodes/velocity");
    const double t = 0.06, a = 4.905;
    EXPECT_NEAR(v[2 * d + 1], a * t, 1e-12);  // rows: floor, ball, flyer
    EXPECT_NEAR(x[2 * d + 1], 5 + a * t * t / 2, 1e-12);
    EXPECT_NEAR(x[2 * d], 5.0, 1e-12);
  }
  // A constant force (or a driver) on a chain is refused: it acts on one-node bodies.
  const fs::path dir = scratch_dir("mixed_force_bad");
  const fs::path scene = write_file(
      dir, "scene.json",
      mixed_scene(2, R"({"type": "auto"})", 0.1, 10,
                  R"(, "forces": [{"type": "constant", "body": "chain", "force": [1, 0]}],
  "drivers": [{"body": "chain", "velocity": [1, 0]}])"));
  const Result bad = run_moreau({"run", scene.string()}, dir);
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.err.find("\"chain\" is a \"chain\" body"), std::string::npos) << bad.err;
}

TEST(Mixed, OutputHasTheSetsAndTheirMaps) {
  const fs::path dir = scratch_dir("mixed_layout");
  const fs::path scene = write_file(dir, "scene.json", mixed_scene(2, R"({"type": "auto"})", 0.01, 10));
  ASSERT_EQ(run_moreau({"run", scene.string(), "--quiet"}, dir).code, 0);
  const std::string out = (dir / "out.h5").string();
  // Bodies in scene order: floor, chain, ball, flyer; models rigid (0) then chain (1).
  EXPECT_EQ(read_doubles(out, "/bodies/model"), (std::vector<double>{0, 1, 0, 0}));
  EXPECT_EQ(read_doubles(out, "/bodies/first_node"), (std::vector<double>{0, 0, 1, 2}));
  EXPECT_EQ(read_doubles(out, "/bodies/nodes"), (std::vector<double>{1, 4, 1, 1}));
  EXPECT_EQ(read_doubles(out, "/bodies/elements"), (std::vector<double>{0, 3, 0, 0}));
  EXPECT_EQ(read_doubles(out, "/rigid.nodes/body"), (std::vector<double>{0, 2, 3}));
  EXPECT_EQ(read_doubles(out, "/chain.nodes/body"), (std::vector<double>(4, 1.0)));
  // The springs as polylines over the chain's nodes (XDMF Mixed: 2, 2, a, b).
  EXPECT_EQ(read_doubles(out, "/chain.springs/cells"), (std::vector<double>{2, 2, 0, 1, 2, 2, 1, 2, 2, 2, 2, 3}));
  EXPECT_EQ(read_doubles(out, "/frames/00000010/chain.nodes/position").size(), 8u);
  EXPECT_EQ(read_doubles(out, "/frames/00000010/chain.springs/tension").size(), 3u);
  EXPECT_EQ(read_doubles(out, "/frames/00000010/rigid.nodes/position").size(), 6u);
  EXPECT_EQ(read_doubles(out, "/frames/00000010/bodies/position").size(), 8u);
  EXPECT_EQ(read_doubles(out, "/contactors/node"), (std::vector<double>{0, 0, 1, 2, 3, 0}));
  // No moreau-output/1 names in a mixed scene: /frames/N/position would not be per body.
  EXPECT_THROW(read_doubles(out, "/frames/00000010/position"), std::runtime_error);
  // A body's reference point: the mean of its nodes.
  const auto x = read_doubles(out, "/frames/00000010/chain.nodes/position");
  const auto p = read_doubles(out, "/frames/00000010/bodies/position");
  EXPECT_NEAR(p[2], (x[0] + x[2] + x[4] + x[6]) / 4, 1e-15);
}

// `models` pairs a modelization with its integrator; a modelization no body uses, and a
// contactor on a node the body does not have, are input errors naming the place.
TEST(Mixed, ModelsSectionAndNodeErrors) {
  const fs::path dir = scratch_dir("mixed_models");
  const std::string ok = R"(, "models": {"rigid": {"integrator": "theta"}, "chain": {"integrator": "chain_theta"}})";
  fs::path scene = write_file(dir, "scene.json", mixed_scene(2, R"({"type": "auto"})", 0.01, 10, ok));
  Result r = run_moreau({"run", scene.string(), "--quiet"}, dir);
  EXPECT_EQ(r.code, 0) << r.err;
  scene = write_file(dir, "bad.json", mixed_scene(2, R"({"type": "auto"})", 0.01, 10, R"(, "models": {"chian": {}})"));
  r = run_moreau({"check", scene.string()}, dir);
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("at /models/chian: no body uses the modelization \"chian\"; did you mean \"chain\"?"), std::string::npos)
      << r.err;
  std::string text = mixed_scene(2);
  text.replace(text.find("\"node\": 3"), 9, "\"node\": 4");
  scene = write_file(dir, "node.json", text);
  r = run_moreau({"check", scene.string()}, dir);
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("/bodies/1/contactors/3/node: body \"chain\" has 4 nodes: expected a node below 4"), std::string::npos)
      << r.err;
}
