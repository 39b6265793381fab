// Restart: a run continued from a frame of its output file ends bit-identical to an
// uninterrupted run, also when the first run was killed (SIGKILL) mid-way.
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <thread>

#include "cli_runner.hpp"
#include "h5_read.hpp"
#include "scenes.hpp"

extern char** environ;

namespace fs = std::filesystem;
using namespace moreau_test;

namespace {

/// A 3D scene with a spinning asymmetric body (exercises the rotation update) and a driver.
std::string spinning_scene(double duration) {
  return R"({
  "format": "moreau-scene/1",
  "dimension": 3,
  "time": {"step": 0.001, "duration": )" + std::to_string(duration) + R"(, "theta": 0.5},
  "gravity": [0, 0, -9.81],
  "bodies": [
    {"name": "top", "position": [0, 0, 1], "velocity": [1, 0, 2], "angular_velocity": [0.3, 5, 0.2],
     "mass": 1.5, "inertia": [0.1, 0.2, 0.3]},
    {"name": "cart", "position": [0, 1, 0], "mass": 1.0, "inertia": [1, 1, 1]}
  ],
  "drivers": [{"body": "cart", "velocity": [0.5, null, 0], "start": 0.01}],
  "output": {"file": "out.h5", "every": 10}
})";
}

/// Three boxes of unequal edges (anisotropic inertia) stacked askew on a plane, with
/// friction: contacts persist across the restart, so it must carry their warm start.
std::string box_stack_scene(const std::string& solver = "") {
  std::string bodies = R"({"name": "floor", "fixed": true, "position": [0, 0, 0],
     "contactors": [{"shape": "plane", "normal": [0, 0, 1], "group": "floor"}]})";
  for (int i = 0; i < 3; ++i)
    bodies += R"(, {"name": "box)" + std::to_string(i) + R"(", "material": "wood", "position": [)" +
              std::to_string(0.03 * i) + ", 0, " + std::to_string(0.05 + 0.1 * i) +
              R"(], "orientation": [0.9998, 0, 0, 0.02], "contactors": [{"shape": "box", "size": [0.4, 0.2, 0.1], "group": "box"}]})";
  return R"({
  "format": "moreau-scene/1",
  "dimension": 3,
  "time": {"step": 0.001, "duration": 0.3},
  "gravity": [0, 0, -9.81],
  "materials": {"wood": {"density": 700}},
  "laws": {"rough": {"type": "coulomb", "friction": 0.5}},
  "bodies": [)" + bodies + R"(],
  "interactions": [{"groups": ["box", "floor"], "law": "rough"}, {"groups": ["box", "box"], "law": "rough"}],)" +
         (solver.empty() ? std::string() : "\n  \"solver\": " + solver + ",") + R"(
  "output": {"file": "out.h5", "every": 50}
})";
}

/// The mixed scene's state at a frame: both node sets and the contacts' impulses.
void expect_same_mixed_frame(const std::string& a, const std::string& b, const std::string& frame) {
  for (const char* f : {"rigid.nodes/position", "rigid.nodes/velocity", "rigid.nodes/angle", "elastic.nodes/displacement",
                        "elastic.nodes/velocity", "contacts/impulse"}) {
    const auto x = read_doubles(a, "/frames/" + frame + "/" + f);
    const auto y = read_doubles(b, "/frames/" + frame + "/" + f);
    ASSERT_EQ(x.size(), y.size()) << f;
    ASSERT_FALSE(x.empty()) << f;
    for (std::size_t i = 0; i < x.size(); ++i) EXPECT_EQ(x[i], y[i]) << f << "[" << i << "] differs";  // bit-identical
  }
}

const char* kFields[] = {"position", "velocity", "orientation", "angular_velocity"};

void expect_same_frame(const std::string& a, const std::string& b, const std::string& frame) {
  for (const char* f : kFields) {
    const auto x = read_doubles(a, "/frames/" + frame + "/" + f);
    const auto y = read_doubles(b, "/frames/" + frame + "/" + f);
    ASSERT_EQ(x.size(), y.size());
    for (std::size_t i = 0; i < x.size(); ++i) EXPECT_EQ(x[i], y[i]) << f << "[" << i << "] differs";  // bit-identical
  }
}

}  // namespace

TEST(Restart, ContinuesBitIdenticallyFromTheLastFrame) {
  const fs::path dir = scratch_dir("restart");
  const fs::path scene = write_file(dir, "scene.json", spinning_scene(0.2));
  ASSERT_EQ(run_moreau({"run", scene.string(), "--out", "full.h5", "--quiet"}, dir).code, 0);
  ASSERT_EQ(run_moreau({"run", scene.string(), "--out", "part.h5", "--steps", "90", "--quiet"}, dir).code, 0);
  Result r = run_moreau({"run", scene.string(), "--restart", "part.h5", "--out", "rest.h5", "--quiet"}, dir);
  ASSERT_EQ(r.code, 0) << r.err;
  expect_same_frame((dir / "full.h5").string(), (dir / "rest.h5").string(), "00000200");
}

TEST(Restart, WithContactsTheWarmStartIsRestoredAndTheContinuationBitIdentical) {
  const fs::path dir = scratch_dir("restart_contacts");
  const fs::path scene = write_file(dir, "scene.json", box_stack_scene());
  ASSERT_EQ(run_moreau({"run", scene.string(), "--out", "full.h5", "--quiet"}, dir).code, 0);
  ASSERT_EQ(run_moreau({"run", scene.string(), "--out", "part.h5", "--steps", "150", "--quiet"}, dir).code, 0);
  ASSERT_FALSE(read_doubles((dir / "part.h5").string(), "/frames/00000150/contacts/impulse").empty());
  Result r = run_moreau({"run", scene.string(), "--restart", "part.h5", "--out", "rest.h5", "--quiet"}, dir);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.err.find("overlap"), std::string::npos) << "no start-of-run overlap warning on a continuation: " << r.err;
  expect_same_frame((dir / "full.h5").string(), (dir / "rest.h5").string(), "00000300");
  const auto a = read_doubles((dir / "full.h5").string(), "/frames/00000300/contacts/impulse");
  const auto b = read_doubles((dir / "rest.h5").string(), "/frames/00000300/contacts/impulse");
  ASSERT_EQ(a.size(), b.size());
  ASSERT_FALSE(a.empty());
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a[i], b[i]) << "impulse[" << i << "] differs";
}

TEST(Restart, AutosMemoryIsSavedWithEachFrameAndRestored) {
  // `auto` with `remember` chooses each solve's first member from what the earlier solves
  // cost: that memory is the solver's state (/frames/N/solver/…), restored on restart.
  const fs::path dir = scratch_dir("restart_auto_memory");
  const std::string solver = R"({"type": "auto", "tolerance": 1e-8, "remember": true})";
  const fs::path scene = write_file(dir, "scene.json", box_stack_scene(solver));
  ASSERT_EQ(run_moreau({"run", scene.string(), "--out", "full.h5", "--quiet"}, dir).code, 0);
  ASSERT_EQ(run_moreau({"run", scene.string(), "--out", "part.h5", "--steps", "150", "--quiet"}, dir).code, 0);
  const std::string full = (dir / "full.h5").string(), part = (dir / "part.h5").string();
  const auto cost = read_doubles(part, "/frames/00000150/solver/member_cost");
  ASSERT_EQ(cost.size(), 5u);
  EXPECT_GT(*std::max_element(cost.begin(), cost.end()), 0.0) << "the memory has learnt something by the restart frame";
  Result r = run_moreau({"run", scene.string(), "--restart", "part.h5", "--out", "rest.h5", "--quiet"}, dir);
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string rest = (dir / "rest.h5").string();
  expect_same_frame(full, rest, "00000300");
  for (const char* f : {"contacts/impulse", "solver/solves", "solver/member_cost", "solver/member_iteration",
                        "solver/member_next_try", "solver/member_try_interval", "solver/at_rest"}) {
    const auto a = read_doubles(full, std::string("/frames/00000300/") + f), b = read_doubles(rest, std::string("/frames/00000300/") + f);
    ASSERT_EQ(a.size(), b.size()) << f;
    ASSERT_FALSE(a.empty()) << f;
    for (std::size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a[i], b[i]) << f << "[" << i << "] differs";
  }
  // A file written before the solver's state was saved (or by a run without `remember`)
  // still restarts: the memory starts empty, so its solves count from the restart.
  const std::string old = (dir / "old.h5").string();
  fs::copy_file(part, old);
  {
    hid_t f = H5Fopen(old.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    for (const char* n : {"solves", "member_cost", "member_iteration", "member_next_try", "member_try_interval", "at_rest"})
      ASSERT_GE(H5Ldelete(f, (std::string("/frames/00000150/solver/") + n).c_str(), H5P_DEFAULT), 0) << n;
    H5Fclose(f);
  }
  Result o = run_moreau({"run", scene.string(), "--restart", old, "--out", "from_old.h5", "--quiet"}, dir);
  ASSERT_EQ(o.code, 0) << o.err;
  const double solves_full = read_doubles(full, "/frames/00000300/solver/solves").at(0);
  const double solves_part = read_doubles(part, "/frames/00000150/solver/solves").at(0);
  const double solves_old = read_doubles((dir / "from_old.h5").string(), "/frames/00000300/solver/solves").at(0);
  EXPECT_GT(solves_part, 0);
  EXPECT_EQ(solves_old, solves_full - solves_part);
}

TEST(Restart, FromAChosenFrameAndIntoTheSameFile) {
  const fs::path dir = scratch_dir("restart_frame");
  const fs::path scene = write_file(dir, "scene.json", spinning_scene(0.1));
  ASSERT_EQ(run_moreau({"run", scene.string(), "--out", "full.h5", "--quiet"}, dir).code, 0);
  fs::copy_file(dir / "full.h5", dir / "again.h5");
  Result r = run_moreau({"run", scene.string(), "--restart", "again.h5", "--frame", "30", "--out", "again.h5", "--quiet"}, dir);
  ASSERT_EQ(r.code, 0) << r.err;
  expect_same_frame((dir / "full.h5").string(), (dir / "again.h5").string(), "00000100");
  Result bad = run_moreau({"run", scene.string(), "--restart", "full.h5", "--frame", "33", "--out", "x.h5"}, dir);
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.err.find("33"), std::string::npos) << bad.err;
}

TEST(Restart, AfterSigkillTheFileIsReadableAndTheRunContinuesBitIdentically) {
  const fs::path dir = scratch_dir("restart_kill");
  const fs::path scene = write_file(dir, "scene.json", spinning_scene(20.0));  // 20000 steps
  // Start a long run, kill it while it writes.
  const std::string path = (dir / "killed.h5").string();
  const pid_t pid = start_moreau({"run", scene.string(), "--out", path, "--quiet"}, dir);
  // Wait until a few frames exist, then kill without warning.
  for (int i = 0; i < 200 && !fs::exists(path); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  std::this_thread::sleep_for(std::chrono::milliseconds(150));
  ASSERT_TRUE(kill_moreau(pid));
  const auto frames = frame_names(path);  // readable after the kill
  ASSERT_FALSE(frames.empty());
  const long last = std::stol(frames.back());
  ASSERT_LT(last, 20000) << "the run finished before the kill: make the test scene longer";
  // The uninterrupted reference, 200 steps past the last frame the killed run wrote.
  const long end = last + 200;
  ASSERT_EQ(run_moreau({"run", scene.string(), "--out", "full.h5", "--quiet", "--steps", std::to_string(end)}, dir).code, 0);
  Result r = run_moreau({"run", scene.string(), "--restart", path, "--out", "cont.h5", "--steps", "200", "--quiet"}, dir);
  ASSERT_EQ(r.code, 0) << r.err;
  char name[16];
  std::snprintf(name, sizeof name, "%08ld", end);
  expect_same_frame((dir / "full.h5").string(), (dir / "cont.h5").string(), name);
}

TEST(Restart, IntoANewFileItsFirstFrameIsTheUninterruptedRunsContactsIncluded) {
  // Once the new file's first frame was rewritten from the state: no contacts (they come
  // from the step before) and no solver figures. Now it is the restart frame, copied.
  const fs::path dir = scratch_dir("restart_first_frame");
  const fs::path scene = write_file(dir, "scene.json", box_stack_scene());
  ASSERT_EQ(run_moreau({"run", scene.string(), "--out", "full.h5", "--quiet"}, dir).code, 0);
  ASSERT_EQ(run_moreau({"run", scene.string(), "--out", "part.h5", "--steps", "150", "--quiet"}, dir).code, 0);
  Result r = run_moreau({"run", scene.string(), "--restart", "part.h5", "--out", "rest.h5", "--quiet"}, dir);
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string full = (dir / "full.h5").string(), rest = (dir / "rest.h5").string();
  EXPECT_EQ(frame_names(rest).front(), "00000150");
  for (const char* frame : {"/frames/00000150", "/frames/00000300"}) {
    const auto names = datasets_under(full, frame);
    ASSERT_EQ(names, datasets_under(rest, frame)) << frame;
    EXPECT_NE(std::find(names.begin(), names.end(), "contacts/key"), names.end());
    for (const auto& n : names) {
      const auto a = read_doubles(full, std::string(frame) + "/" + n), b = read_doubles(rest, std::string(frame) + "/" + n);
      ASSERT_EQ(a.size(), b.size()) << frame << "/" << n;
      for (std::size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a[i], b[i]) << frame << "/" << n << "[" << i << "]";
    }
    for (const char* attr : {"iterations", "error"})
      EXPECT_EQ(read_attribute(full, std::string(frame) + "/solver", attr), read_attribute(rest, std::string(frame) + "/solver", attr))
          << frame << " solver " << attr;
  }
}

TEST(Restart, ADamagedFileIsRefusedAtTheStartNamingTheDataset) {
  // Once accepted (garbage contact keys) or failed mid-run as exit 1 (a NaN orientation).
  const fs::path dir = scratch_dir("restart_damaged");
  const fs::path scene = write_file(dir, "scene.json", box_stack_scene());
  ASSERT_EQ(run_moreau({"run", scene.string(), "--out", "part.h5", "--steps", "150", "--quiet"}, dir).code, 0);
  const std::string part = (dir / "part.h5").string(), frame = "/frames/00000150";
  const auto keys = read_doubles(part, frame + "/contacts/key");
  // The nodes' fields are read from the set's group (/frames/N/orientation is a link to it).
  const std::string nodes = frame + "/rigid.nodes";
  const auto q = read_doubles(part, nodes + "/orientation");
  struct Case {
    const char* name;
    std::string dataset;
    std::vector<double> values;
    hsize_t rows;
    const char* message;
  };
  auto with = [](std::vector<double> v, std::size_t k, double x) {
    v.at(k) = x;
    return v;
  };
  const std::size_t nc = keys.size() / 3;
  const Case cases[] = {
      {"key_big", frame + "/contacts/key", with(keys, 0, 1e12), nc, "is not a contact identity"},
      {"key_other", frame + "/contacts/key", with(keys, 1, 999), nc, "names contactor 999; the scene has 4"},
      {"key_frac", frame + "/contacts/key", with(keys, 2, 0.5), nc, "is not a contact identity"},
      {"impulse", frame + "/contacts/impulse", with(read_doubles(part, frame + "/contacts/impulse"), 4, std::nan("")), nc,
       "row 1 is not finite"},
      {"q_nan", nodes + "/orientation", with(q, 5, std::nan("")), 4, "row 1 is not finite"},
      {"q_norm", nodes + "/orientation", with(q, 4, 2.0), 4, "row 1 is not a unit quaternion"},
      {"shape", nodes + "/position", {0, 0, 0}, 1, "expected 12 values (4 rows of 3), found 3"},
  };
  for (const auto& c : cases) {
    const std::string copy = (dir / (std::string(c.name) + ".h5")).string();
    fs::copy_file(part, copy, fs::copy_options::overwrite_existing);
    replace_doubles(copy, c.dataset, c.values, c.rows);
    Result r = run_moreau({"run", scene.string(), "--restart", copy, "--out", "rest.h5", "--quiet"}, dir);
    EXPECT_EQ(r.code, 2) << c.name << ": " << r.err;
    EXPECT_NE(r.err.find(copy + ": at " + c.dataset + ": "), std::string::npos) << c.name << ": " << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << c.name << ": " << r.err;
    EXPECT_FALSE(fs::exists(dir / "rest.h5")) << c.name << ": bad input leaves no output";
  }
  // A group under /frames that is not a frame.
  const std::string odd = (dir / "odd.h5").string();
  fs::copy_file(part, odd);
  {
    hid_t f = H5Fopen(odd.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    H5Gclose(H5Gcreate2(f, "/frames/latest", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
    H5Fclose(f);
  }
  Result r = run_moreau({"run", scene.string(), "--restart", odd, "--out", "rest.h5", "--quiet"}, dir);
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("at /frames/latest: not a frame"), std::string::npos) << r.err;
}

TEST(Restart, RigidAndElasticBodiesContinueBitIdenticallyAlsoAfterSigkill) {
  const fs::path dir = scratch_dir("restart_mixed");
  const fs::path scene = write_file(dir, "scene.json", slab_and_disks_scene(0.3));
  ASSERT_EQ(run_moreau({"run", scene.string(), "--out", "full.h5", "--quiet"}, dir).code, 0);
  ASSERT_EQ(run_moreau({"run", scene.string(), "--out", "part.h5", "--steps", "150", "--quiet"}, dir).code, 0);
  ASSERT_FALSE(read_doubles((dir / "part.h5").string(), "/frames/00000150/contacts/impulse").empty());
  Result r = run_moreau({"run", scene.string(), "--restart", "part.h5", "--out", "rest.h5", "--quiet"}, dir);
  ASSERT_EQ(r.code, 0) << r.err;
  expect_same_mixed_frame((dir / "full.h5").string(), (dir / "rest.h5").string(), "00000300");

  // Killed mid-run: the file stays readable and the run continues from its last frame.
  const fs::path long_scene = write_file(dir, "long.json", slab_and_disks_scene(100.0));
  const std::string path = (dir / "killed.h5").string();
  const pid_t pid = start_moreau({"run", long_scene.string(), "--out", path, "--quiet"}, dir);
  for (int i = 0; i < 300 && !fs::exists(path); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  ASSERT_TRUE(kill_moreau(pid));
  const auto frames = frame_names(path);
  ASSERT_FALSE(frames.empty());
  const long last = std::stol(frames.back());
  ASSERT_LT(last, 100000);
  const long end = last + 50;
  ASSERT_EQ(run_moreau({"run", long_scene.string(), "--out", "long_full.h5", "--quiet", "--steps", std::to_string(end)}, dir).code, 0);
  Result c = run_moreau({"run", long_scene.string(), "--restart", path, "--out", "cont.h5", "--steps", "50", "--quiet"}, dir);
  ASSERT_EQ(c.code, 0) << c.err;
  char name[16];
  std::snprintf(name, sizeof name, "%08ld", end);
  expect_same_mixed_frame((dir / "long_full.h5").string(), (dir / "cont.h5").string(), name);
}
