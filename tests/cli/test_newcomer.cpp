// What a new user runs into first (issue 11, point 5): suggestions for every mistyped name,
// `--version`, grid parameters from the scene, a word when nothing can collide (or when a
// law can gain energy), Ctrl-C, the force network drawn through contact points (on walls
// and on meshes), and what docs/output.md and docs/scene.md state (contact conventions,
// drivers, the segment's axis, where relative paths resolve), read back from runs.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include "cli_runner.hpp"
#include "h5_read.hpp"
#include "scenes.hpp"

extern char** environ;
namespace fs = std::filesystem;
using namespace moreau_test;

namespace {

std::string replace(std::string s, const std::string& from, const std::string& to) {
  const auto p = s.find(from);
  if (p == std::string::npos) throw std::logic_error("scene template has no " + from);
  return s.replace(p, from.size(), to);
}

/// A disk on a floor segment, a second disk on it: contacts disk–floor and disk–disk.
std::string stack_scene(const std::string& detection = R"("alert": 0.001)", const std::string& extra = "") {
  return R"({"format": "moreau-scene/1", "dimension": 2, "time": {"step": 0.001, "duration": 0.01},
  "gravity": [0, -9.81], "materials": {"rock": {"density": 2000}},
  "laws": {"rough": {"type": "coulomb", "friction": 0.3}},
  "bodies": [
    {"name": "floor", "fixed": true, "position": [0, -0.05], "contactors": [{"shape": "segment", "length": 2, "thickness": 0.1, "group": "wall"}]},
    {"name": "low", "material": "rock", "position": [0.3, 0.1], "contactors": [{"shape": "disk", "radius": 0.1, "group": "grain"}]},
    {"name": "high", "material": "rock", "position": [0.3, 0.3], "contactors": [{"shape": "disk", "radius": 0.1, "group": "grain"}]}
  ],
  "interactions": [{"groups": ["grain", "wall"], "law": "rough"}, {"groups": ["grain", "grain"], "law": "rough"}],
  "detection": {)" + detection + R"(},
  "output": {"every": 5})" + extra + "}";
}

Result check_text(const std::string& name, const std::string& scene) {
  const fs::path dir = scratch_dir(name);
  return run_moreau({"check", write_file(dir, "scene.json", scene).string()}, dir);
}

}  // namespace

TEST(Newcomer, VersionNamesTheProgramAndItsContracts) {
  const Result r = run_moreau({"--version"});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out.rfind("moreau 0.", 0), 0u) << r.out;
  for (const char* part : {"plugin ABI ", "SDK ", "moreau-scene/1", "moreau-output/2"})
    EXPECT_NE(r.out.find(part), std::string::npos) << part << " in: " << r.out;
}

// Every kind of name a scene or the command line holds gets the nearest valid one,
// whatever the case.
TEST(Newcomer, DidYouMeanForEveryUnknownNameIgnoringCase) {
  const std::string base = stack_scene();
  struct Case {
    std::string from, to, expected;
  };
  const std::vector<Case> cases = {
      {R"("shape": "disk", "radius": 0.1, "group": "grain"}]},
    {"name": "high")", R"("shape": "Disk", "radius": 0.1, "group": "grain"}]},
    {"name": "high")", "unknown shape 'Disk'; did you mean 'disk'?"},
      {R"("type": "coulomb")", R"("type": "Coulomb")", "unknown law 'Coulomb'; did you mean 'coulomb'?"},
      {R"("output": {"every": 5})", R"("output": {"every": 5}, "solver": {"type": "NLGS"})",
       "unknown solver 'NLGS'; did you mean 'nlgs'?"},
      {R"("alert": 0.001)", R"("alert": 0.001, "broadphase": "Grid")", "unknown broadphase 'Grid'; did you mean 'grid'?"},
      {R"("output": {"every": 5})", R"("output": {"every": 5}, "hooks": [{"type": "energylog"}])",
       "unknown hook 'energylog'; did you mean 'energy_log'?"},
      {R"("output": {"every": 5})", R"("output": {"every": 5}, "forces": [{"type": "Constant", "body": "low"}])",
       "unknown force 'Constant'; did you mean 'constant'?"},
      {R"("time": {"step": 0.001, "duration": 0.01})", R"("time": {"step": 0.001, "duration": 0.01, "integrator": "Theta"})",
       "unknown integrator 'Theta'; did you mean 'theta'?"},
      {R"("name": "floor", "fixed")", R"("name": "floor", "model": "Rigid", "fixed")",
       "unknown modelization 'Rigid'; did you mean 'rigid'?"},
      {R"("gravity")", R"("Gravity")", "unknown key \"Gravity\"; did you mean \"gravity\"?"},
      {R"("alert": 0.001})", R"("alert": 0.001}, "solver": {"type": "nlgs", "on_failure": "Stop"})",
       "at /solver/on_failure: expected \"warn\" or \"stop\"; did you mean \"stop\"?"},
      {R"("alert": 0.001)", R"("Alert": 0.001)", "unknown key \"Alert\"; did you mean \"alert\"?"},
      {R"("material": "rock", "position": [0.3, 0.3])", R"("material": "Rock", "position": [0.3, 0.3])",
       "unknown material \"Rock\"; did you mean \"rock\"?"},
      {R"("law": "rough"}, {"groups": ["grain", "grain"])", R"("law": "Rough"}, {"groups": ["grain", "grain"])",
       "no law named \"Rough\" in \"laws\"; did you mean \"rough\"?"},
      {R"({"groups": ["grain", "wall"])", R"({"groups": ["grains", "wall"])",
       "no contactor has group \"grains\"; did you mean \"grain\"?"},
      {R"("output": {"every": 5})", R"("output": {"every": 5, "display": "shape"})",
       "expected one of \"shapes\", \"points\"; did you mean \"shapes\"?"},
      {R"("output": {"every": 5})", R"("output": {"every": 5}, "drivers": [{"body": "Low", "velocity": [0, 0]}])",
       "no body named \"Low\"; did you mean \"low\"?"},
  };
  for (const auto& c : cases) {
    const Result r = check_text("dym", replace(base, c.from, c.to));
    EXPECT_EQ(r.code, 2) << c.to;
    EXPECT_NE(r.err.find(c.expected), std::string::npos) << "expected: " << c.expected << "\ngot:\n" << r.err;
  }
  // A group whose only contactors have an unknown shape: one error, at the shape (not a
  // second "no contactor has group" at each interaction naming it).
  const std::string disk = R"("shape": "disk")";
  const Result only = check_text("dym_group", replace(replace(base, disk, R"("shape": "DISK")"), disk, R"("shape": "DISK")"));
  EXPECT_EQ(only.code, 2);
  EXPECT_NE(only.err.find("unknown shape 'DISK'; did you mean 'disk'?"), std::string::npos) << only.err;
  EXPECT_EQ(only.err.find("no contactor has group"), std::string::npos) << only.err;
  // The command line: commands and options.
  const Result command = run_moreau({"rnu", "scene.json"});
  EXPECT_EQ(command.code, 2);
  EXPECT_NE(command.err.find("unknown command 'rnu'; did you mean 'run'?"), std::string::npos) << command.err;
  EXPECT_EQ(command.err.find("A subcommand is required"), std::string::npos) << command.err;
  const Result option = run_moreau({"run", "scene.json", "--Steps", "3"});
  EXPECT_EQ(option.code, 2);
  EXPECT_NE(option.err.find("unknown option --Steps; did you mean \"--steps\"?"), std::string::npos) << option.err;
  const Result short_option = run_moreau({"run", "scene.json", "-o", "out.h5"});
  EXPECT_EQ(short_option.code, 2);
  EXPECT_NE(short_option.err.find("unknown option -o; did you mean \"--out\"?"), std::string::npos) << short_option.err;
}

TEST(Newcomer, GridBroadPhaseParametersFromTheScene) {
  const std::string scene = stack_scene(R"("alert": 0.001, "broadphase": {"type": "grid", "cell": 0.5})");
  const fs::path dir = scratch_dir("grid_params");
  const fs::path path = write_file(dir, "scene.json", scene);
  Result r = run_moreau({"check", path.string()}, dir);
  EXPECT_EQ(r.code, 0) << r.err;
  r = run_moreau({"run", path.string(), "--quiet"}, dir);
  EXPECT_EQ(r.code, 0) << r.err;
  const Result bad = check_text("grid_params_bad", replace(scene, R"("cell": 0.5)", R"("cel": 0.5)"));
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.err.find("at /detection/broadphase/cel: unknown key \"cel\"; did you mean \"cell\"?"), std::string::npos)
      << bad.err;
  const Result negative = check_text("grid_params_negative", replace(scene, R"("cell": 0.5)", R"("cell": -1)"));
  EXPECT_EQ(negative.code, 2);
  EXPECT_NE(negative.err.find("at /detection/broadphase/cell: value -1 out of range"), std::string::npos) << negative.err;
}

TEST(Newcomer, WarnsWhenContactorsCanNeverCollide) {
  // No interactions at all.
  std::string none = stack_scene();
  none = replace(none, R"("interactions": [{"groups": ["grain", "wall"], "law": "rough"}, {"groups": ["grain", "grain"], "law": "rough"}],)", "");
  Result r = check_text("no_interactions", none);
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("warning: "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("no \"interactions\": nothing will collide"), std::string::npos) << r.err;
  // The walls left out.
  r = check_text("group_left_out", replace(stack_scene(), R"({"groups": ["grain", "wall"], "law": "rough"}, )", ""));
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("1 contactor of group \"wall\" is in no interaction: nothing will collide with it"), std::string::npos)
      << r.err;
  // Contact-free scenes (no contactors) and complete ones say nothing.
  EXPECT_EQ(check_text("projectile", projectile_scene()).err.find("warning"), std::string::npos);
  EXPECT_EQ(check_text("complete", stack_scene()).err.find("warning"), std::string::npos);
}

// Newton's restitution with friction can gain energy at impacts off a body's centre
// (tests/validation/test_bounce.cpp measures it): a law with e > 0.8 and μ > 0 that reaches
// a moving polygon is named in a warning; disks (normals through their centres), a
// frictionless law and e ≤ 0.8 say nothing.
TEST(Newcomer, WarnsWhereRestitutionWithFrictionCanGainEnergy) {
  const std::string law = R"("rough": {"type": "coulomb", "friction": 0.3})";
  const std::string square =
      R"({"shape": "polygon", "vertices": [[-0.1, -0.1], [0.1, -0.1], [0.1, 0.1], [-0.1, 0.1]], "group": "grain"})";
  const std::string disk = R"({"shape": "disk", "radius": 0.1, "group": "grain"})";
  const auto scene = [&](const std::string& laws, bool squares) {
    std::string s = replace(stack_scene(), law, laws);
    return squares ? replace(s, disk, square) : s;
  };
  const std::string bouncy = R"("rough": {"type": "coulomb", "friction": 0.3, "restitution": 0.9})";
  Result r = check_text("restitution_squares", scene(bouncy, true));
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("warning: "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("law \"rough\": Newton restitution (e = 0.9) with friction (mu = 0.3) can gain energy at an "
                       "impact off a body's centre (group \"grain\""),
            std::string::npos)
      << r.err;
  EXPECT_EQ(check_text("restitution_disks", scene(bouncy, false)).err.find("warning"), std::string::npos);
  EXPECT_EQ(check_text("restitution_frictionless",
                       scene(R"("rough": {"type": "coulomb", "friction": 0, "restitution": 1})", true))
                .err.find("warning"),
            std::string::npos);
  EXPECT_EQ(check_text("restitution_low", scene(R"("rough": {"type": "coulomb", "friction": 0.3, "restitution": 0.8})", true))
                .err.find("warning"),
            std::string::npos);
}

// Lines of the force network go through the contact point: a disk's end is its centre,
// the floor's (far larger) is the contact point, not the floor's centre.
TEST(Newcomer, ForceNetworkLinesEndAtContactPointsOnWalls) {
  const fs::path dir = scratch_dir("network");
  const fs::path scene = write_file(dir, "scene.json", stack_scene());
  ASSERT_EQ(run_moreau({"run", scene.string(), "--quiet"}, dir).code, 0);
  const std::string file = (dir / "out.h5").string(), frame = "/frames/00000010/";
  const auto bodies = read_doubles(file, frame + "contacts/bodies");
  const auto point = read_doubles(file, frame + "contacts/point");
  const auto network = read_doubles(file, frame + "contacts/network");
  const auto position = read_doubles(file, frame + "position");
  const std::size_t nc = bodies.size() / 2;
  ASSERT_EQ(nc, 2u);
  ASSERT_EQ(network.size(), nc * 3 * 2);
  int walls = 0;
  for (std::size_t c = 0; c < nc; ++c)
    for (int side = 0; side < 2; ++side) {
      const int b = static_cast<int>(bodies[2 * c + side]);
      const double* end = &network[6 * c + (side == 0 ? 0 : 4)];
      const double* expected = b == 0 ? &point[2 * c] : &position[2 * b];  // body 0: the floor
      walls += b == 0;
      for (int k = 0; k < 2; ++k) EXPECT_NEAR(end[k], expected[k], 1e-6) << "contact " << c << " body " << b;
      for (int k = 0; k < 2; ++k) EXPECT_NEAR(network[6 * c + 2 + k], point[2 * c + k], 1e-6) << "middle point";
    }
  EXPECT_EQ(walls, 1);
}

// On a mesh body (issue 12) a line's end is the contact point, never a node of the mesh
// nor its mean: a rigid disk resting on an elastic slab is drawn from its centre to the
// contact point on the slab; the floor (0.5 m reach, the slab's nodes 0.2 m about their
// mean: not 4 times larger) from its centre.
TEST(Newcomer, ForceNetworkLinesEndAtContactPointsOnMeshes) {
  const fs::path dir = scratch_dir("network_mesh");
  const fs::path scene = write_file(dir, "scene.json", slab_and_disks_scene(0.1));
  ASSERT_EQ(run_moreau({"run", scene.string(), "--quiet"}, dir).code, 0);
  const std::string file = (dir / "out.h5").string(), frame = "/frames/00000100/";
  const auto bodies = read_doubles(file, frame + "contacts/bodies");
  const auto point = read_doubles(file, frame + "contacts/point");
  const auto network = read_doubles(file, frame + "contacts/network");
  const auto position = read_doubles(file, frame + "bodies/position");
  const std::size_t nc = bodies.size() / 2;
  ASSERT_EQ(network.size(), nc * 3 * 2);
  int on_mesh = 0, disks = 0;
  for (std::size_t c = 0; c < nc; ++c)
    for (int side = 0; side < 2; ++side) {
      const int b = static_cast<int>(bodies[2 * c + side]);  // 0 floor, 1 slab, 2 and 3 disks
      const double* end = &network[6 * c + (side == 0 ? 0 : 4)];
      const double* expected = b == 1 ? &point[2 * c] : &position[2 * b];
      on_mesh += b == 1;
      disks += b >= 2;
      for (int k = 0; k < 2; ++k) EXPECT_NEAR(end[k], expected[k], 1e-6) << "contact " << c << " body " << b;
      for (int k = 0; k < 2; ++k) EXPECT_NEAR(network[6 * c + 2 + k], point[2 * c + k], 1e-6) << "middle point";
    }
  EXPECT_EQ(on_mesh, static_cast<int>(nc));  // every contact has the slab on one side
  EXPECT_GE(disks, 1);                       // disk a on the slab (b is still falling)
}

// Ctrl-C stops after the step under way: exit 128 + SIGINT, a complete self-contained
// output (no frames folder), and a line giving the --restart command, which continues.
TEST(Newcomer, CtrlCLeavesACompleteOutputAndSaysHowToContinue) {
  const fs::path dir = scratch_dir("ctrl_c");
  const fs::path scene =
      write_file(dir, "scene.json", projectile_scene("", "\"step\": 0.0001, \"duration\": 100000"));
  std::string exe = MOREAU_EXE, run = "run", sc = scene.string(), o = "--out", path = (dir / "out.h5").string();
  char* argv[] = {exe.data(), run.data(), sc.data(), o.data(), path.data(), nullptr};
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_addopen(&fa, 2, (dir / "err.txt").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&fa, 1, (dir / "out.txt").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  pid_t pid;
  ASSERT_EQ(posix_spawn(&pid, MOREAU_EXE, &fa, nullptr, argv, environ), 0);
  posix_spawn_file_actions_destroy(&fa);
  // Until the run is under way (frames every 5 steps: a few are listed).
  for (int i = 0; i < 600 && !fs::exists(dir / "out.h5.frames" / "00000020.h5"); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  kill(pid, SIGINT);
  int status = 0;
  for (int i = 0; i < 600 && waitpid(pid, &status, WNOHANG) == 0; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  if (waitpid(pid, &status, WNOHANG) == 0) {
    kill(pid, SIGKILL);
    waitpid(pid, &status, 0);
    FAIL() << "the run did not end after Ctrl-C";
  }
  ASSERT_TRUE(WIFEXITED(status)) << "ended by a signal";
  EXPECT_EQ(WEXITSTATUS(status), 128 + SIGINT);
  std::ifstream in(dir / "err.txt");
  const std::string err((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string hint = "continue with:\n  moreau run " + scene.string() + " --out " + path + " --restart " + path;
  EXPECT_NE(err.find(hint), std::string::npos) << err;
  EXPECT_FALSE(fs::exists(dir / "out.h5.frames")) << "the output is one self-contained file";
  const auto frames = frame_names(path);
  ASSERT_GE(frames.size(), 5u);
  EXPECT_EQ(read_doubles(path, "/frames/" + frames.back() + "/position").size(), 4u);
  // The line's command continues the run.
  const Result more = run_moreau({"run", scene.string(), "--out", path, "--restart", path, "--steps", "10", "--quiet"}, dir);
  EXPECT_EQ(more.code, 0) << more.err;
  EXPECT_GT(frame_names(path).size(), frames.size());
}

namespace {
/// A block sliding on a fixed floor (friction acting) and a ball hovering 0.5 mm above it
/// (inside the 1 mm alert: an open contact), one step; 2D or 3D.
std::string contact_conventions_scene(int d) {
  const std::string block = d == 2 ? R"({"shape": "polygon", "vertices": [[-0.05, -0.05], [0.05, -0.05], [0.05, 0.05], [-0.05, 0.05]], "group": "g"})"
                                   : R"({"shape": "box", "size": [0.1, 0.1, 0.1], "group": "g"})";
  const std::string ball = std::string(R"({"shape": ")") + (d == 2 ? "disk" : "sphere") + R"(", "radius": 0.05, "group": "g"})";
  const std::string floor = d == 2 ? R"({"shape": "segment", "length": 4, "thickness": 0.02, "group": "w"})"
                                   : R"({"shape": "box", "size": [4, 4, 0.02], "group": "w"})";
  const auto vec = [d](double x, double y) {
    return "[" + std::to_string(x) + ", " + (d == 2 ? std::to_string(y) : "0, " + std::to_string(y)) + "]";
  };
  // Gravity and the floor along the last axis: y in 2D, z in 3D.
  return R"({"format": "moreau-scene/1", "dimension": )" + std::to_string(d) + R"(,
  "time": {"step": 0.001, "duration": 0.001}, "gravity": )" + vec(0, -9.81) + R"(,
  "materials": {"wood": {"density": 700}},
  "laws": {"rough": {"type": "coulomb", "friction": 0.4}},
  "interactions": [{"groups": ["g", "w"], "law": "rough"}],
  "detection": {"alert": 0.001}, "solver": {"type": "nlgs", "tolerance": 1e-12, "max_iterations": 1000},
  "output": {"file": "out.h5", "every": 1},
  "bodies": [
    {"name": "floor", "fixed": true, "position": )" + vec(0, -0.01) + R"(, "contactors": [)" + floor + R"(]},
    {"name": "block", "material": "wood", "position": )" + vec(0, 0.05) + R"(, "velocity": )" + vec(2, 0) +
         R"(, "contactors": [)" + block + R"(]},
    {"name": "ball", "material": "wood", "position": )" + vec(1, 0.0505) + R"(, "contactors": [)" + ball + R"(]}]})";
}
}  // namespace

// docs/output.md, "Contacts", read back from a run as a user would: `force` is the force on
// the first body of `bodies` (normal from the second toward the first, normal_force > 0
// pressing them apart, friction against the first body's sliding), `force` = the impulse
// in the documented local frame (2D t = (−n_y, n_x); 3D t = n × a/|n × a|, a the axis least
// aligned with n, s = n × t) over h, and open contacts are listed with zero impulse and
// force, status 0 and their gap.
TEST(Newcomer, ContactOutputFollowsTheDocumentedConventions) {
  for (int d : {2, 3}) {
    const fs::path dir = scratch_dir("conventions" + std::to_string(d));
    const fs::path scene = write_file(dir, "scene.json", contact_conventions_scene(d));
    const Result r = run_moreau({"run", scene.string(), "--quiet"}, dir);
    ASSERT_EQ(r.code, 0) << r.err;
    const std::string file = (dir / "out.h5").string(), frame = "/frames/00000001/contacts/";
    const auto bodies = read_doubles(file, frame + "bodies"), normal = read_doubles(file, frame + "normal");
    const auto force = read_doubles(file, frame + "force"), impulse = read_doubles(file, frame + "impulse");
    const auto normal_force = read_doubles(file, frame + "normal_force"), gap = read_doubles(file, frame + "gap");
    const auto status = read_doubles(file, frame + "status");
    const std::size_t nc = gap.size();
    ASSERT_GE(nc, 2u) << "d = " << d;
    const double h = 0.001;
    int sliding = 0, open = 0;
    for (std::size_t c = 0; c < nc; ++c) {
      const double* n = &normal[d * c];
      // The local frame of `impulse`, as docs/output.md states it.
      double t[3] = {0, 0, 0}, s[3] = {0, 0, 0};
      if (d == 2) {
        t[0] = -n[1];
        t[1] = n[0];
      } else {
        double a[3] = {0, 0, 0};
        const double ax = std::fabs(n[0]), ay = std::fabs(n[1]), az = std::fabs(n[2]);
        a[ax <= ay && ax <= az ? 0 : ay <= az ? 1 : 2] = 1;
        const double c0[3] = {n[1] * a[2] - n[2] * a[1], n[2] * a[0] - n[0] * a[2], n[0] * a[1] - n[1] * a[0]};
        const double len = std::sqrt(c0[0] * c0[0] + c0[1] * c0[1] + c0[2] * c0[2]);
        for (int k = 0; k < 3; ++k) t[k] = c0[k] / len;
        s[0] = n[1] * t[2] - n[2] * t[1];
        s[1] = n[2] * t[0] - n[0] * t[2];
        s[2] = n[0] * t[1] - n[1] * t[0];
      }
      const double* p = &impulse[d * c];
      double fn = 0;
      for (int k = 0; k < d; ++k) {
        const double expected = (p[0] * n[k] + p[1] * t[k] + (d == 3 ? p[2] * s[k] : 0.0)) / h;
        EXPECT_NEAR(force[d * c + k], expected, 1e-9 * (1 + std::fabs(expected))) << "d " << d << " contact " << c;
        fn += force[d * c + k] * n[k];
      }
      EXPECT_NEAR(normal_force[c], fn, 1e-9 * (1 + std::fabs(fn)));
      // Which body: the floor is body 0, below the others along the last axis.
      const int first = static_cast<int>(bodies[2 * c]), second = static_cast<int>(bodies[2 * c + 1]);
      ASSERT_TRUE(first == 0 || second == 0);
      const double up = first == 0 ? -1.0 : 1.0;  // the floor is the second body: the normal points up
      EXPECT_NEAR(n[d - 1], up, 1e-9) << "the normal points from the second body toward the first";
      if (gap[c] > 1e-4) {  // the ball, 0.5 mm above the floor
        ++open;
        EXPECT_EQ(status[c], 0.0);
        EXPECT_EQ(normal_force[c], 0.0);
        for (int k = 0; k < d; ++k) EXPECT_EQ(impulse[d * c + k], 0.0);
      } else {  // the block, sliding in +x: pressed up, braked in −x (the floor gets the opposite)
        ++sliding;
        EXPECT_GT(status[c], 0.0);
        EXPECT_GT(normal_force[c], 0.0);
        EXPECT_LT(up * force[d * c], 0.0) << "friction on the first body opposes its sliding";
      }
    }
    EXPECT_EQ(open, 1) << "d = " << d;
    EXPECT_GE(sliding, 1) << "d = " << d;
  }
}

// docs/scene.md, "Drivers": a fixed body with a driver moves (its free components stay at
// rest: no gravity on a fixed body); where two drivers' windows overlap on a component the
// one listed last wins; a component only one driver names follows it.
TEST(Newcomer, DriversOnFixedBodiesAndOverlappingDrivers) {
  const fs::path dir = scratch_dir("drivers");
  const fs::path scene = write_file(dir, "scene.json", R"({"format": "moreau-scene/1", "dimension": 2,
  "time": {"step": 0.01, "duration": 0.1}, "gravity": [0, -9.81],
  "bodies": [
    {"name": "piston", "fixed": true, "position": [0, 0], "mass": 1, "inertia": 1},
    {"name": "cart", "position": [0, 0], "mass": 1, "inertia": 1}],
  "drivers": [
    {"body": "piston", "velocity": [0.5, null]},
    {"body": "cart", "velocity": [1, null], "end": 0.1},
    {"body": "cart", "velocity": [2, 3], "start": 0.05}],
  "output": {"file": "out.h5", "every": 1}})");
  const Result r = run_moreau({"run", scene.string(), "--quiet"}, dir);
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string file = (dir / "out.h5").string();
  for (int step : {2, 5, 10}) {
    char frame[64];
    std::snprintf(frame, sizeof frame, "/frames/%08d/", step);
    const auto v = read_doubles(file, std::string(frame) + "velocity");
    EXPECT_DOUBLE_EQ(v[0], 0.5) << "the fixed piston moves as driven, step " << step;
    EXPECT_DOUBLE_EQ(v[1], 0.0) << "its free component stays at rest, step " << step;
    // The cart: the second driver alone up to t⁺ < 0.05 (x imposed, y under gravity), then
    // both, the last listed winning on x and alone on y.
    const double t = step * 0.01;
    if (t < 0.05 - 1e-12) {
      EXPECT_DOUBLE_EQ(v[2], 1.0) << "step " << step;
      EXPECT_NEAR(v[3], -9.81 * t, 1e-12) << "y is free: gravity, step " << step;
    } else {
      EXPECT_DOUBLE_EQ(v[2], 2.0) << "the driver listed last wins, step " << step;
      EXPECT_DOUBLE_EQ(v[3], 3.0) << "step " << step;
    }
  }
}

// docs/scene.md: a segment's core lies along the x axis of its frame and turns with the
// body's angle (a disk over x = 0.45 lands on a floor of length 1; over x = 0.6 it falls
// past; the same floor turned by π/2 is a wall that the first disk misses). And where
// relative paths resolve: `output.file` in the working folder, a hook's file beside the
// output (`--out` moves it along).
TEST(Newcomer, SegmentAxisAndRelativePaths) {
  const auto scene = [](double angle) {
    return R"({"format": "moreau-scene/1", "dimension": 2, "time": {"step": 0.001, "duration": 0.3},
  "gravity": [0, -9.81], "laws": {"l": {"type": "coulomb"}}, "interactions": [{"groups": ["g", "w"], "law": "l"}],
  "bodies": [
    {"name": "floor", "fixed": true, "position": [0, 0], "angle": )" + std::to_string(angle) + R"(,
     "contactors": [{"shape": "segment", "length": 1, "thickness": 0.02, "group": "w"}]},
    {"name": "on", "position": [0.45, 0.1], "mass": 1, "inertia": 1, "contactors": [{"shape": "disk", "radius": 0.02, "group": "g"}]},
    {"name": "off", "position": [0.6, 0.1], "mass": 1, "inertia": 1, "contactors": [{"shape": "disk", "radius": 0.02, "group": "g"}]}],
  "hooks": [{"type": "energy_log", "file": "energy.csv", "every": 100}],
  "output": {"file": "flat.h5", "every": 100}})";
  };
  const fs::path dir = scratch_dir("segment_axis");
  fs::create_directories(dir / "scenes");
  fs::create_directories(dir / "work");
  const fs::path flat = write_file(dir / "scenes", "flat.json", scene(0));
  // Run from work/: output.file lands there, and the hook's file beside it.
  Result r = run_moreau({"run", flat.string(), "--quiet"}, dir / "work");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir / "work" / "flat.h5")) << "output.file resolves in the working folder";
  EXPECT_TRUE(fs::exists(dir / "work" / "energy.csv")) << "a hook's file resolves beside the output";
  EXPECT_FALSE(fs::exists(dir / "scenes" / "flat.h5"));
  auto x = read_doubles((dir / "work" / "flat.h5").string(), "/frames/00000300/position");
  EXPECT_NEAR(x[3], 0.01 + 0.02, 1e-4) << "the disk over x = 0.45 rests on the floor (length 1 along x)";
  EXPECT_LT(x[5], -0.2) << "the disk over x = 0.6 falls past the end";
  // --out moves the output and the hook's file along.
  fs::create_directories(dir / "elsewhere");
  r = run_moreau({"run", flat.string(), "--out", (dir / "elsewhere" / "moved.h5").string(), "--quiet"}, dir / "work");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir / "elsewhere" / "energy.csv"));
  // Turned by π/2 the segment is a wall along y through the origin: both disks fall.
  const fs::path wall = write_file(dir / "scenes", "wall.json", scene(1.5707963267948966));
  r = run_moreau({"run", wall.string(), "--out", "wall.h5", "--quiet"}, dir / "work");
  ASSERT_EQ(r.code, 0) << r.err;
  x = read_doubles((dir / "work" / "wall.h5").string(), "/frames/00000300/position");
  EXPECT_LT(x[3], -0.2);
  EXPECT_LT(x[5], -0.2);
}
