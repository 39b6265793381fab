// Write failures during a run (issue 11): a full disk (tmpfs of 2 MB and 8 MB) and a
// file-size limit (ulimit -f). Each ends with exit 1, a message naming the file and the
// OS's reason, no temporary file, and either nothing (a failure at the start) or what a
// killed run leaves — OUT.h5 listing every complete frame, with OUT.h5.frames/ — which
// `--restart OUT.h5 --out OUT.h5` continues and gathers. Also OUT.h5.lock: a second run
// writing the same file is refused.
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/mount.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include "cli_runner.hpp"
#include "h5_read.hpp"
#include "kernel/io/h5.hpp"
#include <moreau/error.hpp>

extern char** environ;
namespace fs = std::filesystem;
using namespace moreau_test;

namespace {

/// A 2D projectile written every step: many small frames, and a gathered file at the end
/// that is much larger than any of them.
std::string many_frames_scene(double duration = 1.0) {
  return R"({"format": "moreau-scene/1", "dimension": 2, "time": {"step": 0.001, "duration": )" +
         std::to_string(duration) + R"(}, "gravity": [0, -9.81],
  "bodies": [{"name": "ball", "position": [0, 1], "velocity": [2, 3], "mass": 2.0, "inertia": 0.1}],
  "output": {"file": "out.h5", "every": 1}})";
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

/// `moreau ARGS` in `dir` under `ulimit -f KB` (the limit in KiB, as bash counts it), with
/// environment assignments `env` ("NAME=value ...").
Result run_limited(const std::vector<std::string>& args, const fs::path& dir, long kb, const std::string& env = "") {
  std::string cmd = "ulimit -f " + std::to_string(kb) + "; " + env + " exec '" MOREAU_EXE "'";
  for (const auto& a : args) cmd += " '" + a + "'";
  cmd += " > '" + (dir / ".out").string() + "' 2> '" + (dir / ".err").string() + "'";
  write_file(dir, ".run.sh", "cd '" + dir.string() + "'\n" + cmd + "\n");
  const int status = std::system(("bash '" + (dir / ".run.sh").string() + "'").c_str());
  Result r;
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = slurp(dir / ".out");
  r.err = slurp(dir / ".err");
  return r;
}

std::vector<fs::path> part_files(const fs::path& dir) {
  std::vector<fs::path> parts;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.path().extension() == ".part" || e.path().extension() == ".tmp") parts.push_back(e.path());
  return parts;
}

/// What a failed write must leave: checked for every outcome.
void expect_clean_failure(const Result& r, const fs::path& dir, const fs::path& out, const std::string& reason) {
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_NE(r.err.find("run failed: "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(reason), std::string::npos) << "the OS's reason \"" << reason << "\" in:\n" << r.err;
  EXPECT_NE(r.err.find("cannot write "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("out.h5"), std::string::npos) << "the path in:\n" << r.err;
  EXPECT_EQ(r.err.find("internal error"), std::string::npos) << r.err;
  EXPECT_TRUE(part_files(dir).empty()) << "a temporary file was left: " << part_files(dir).front();
  const fs::path folder = out.string() + ".frames";
  if (fs::exists(folder)) {
    // The killed-run layout: every listed frame complete, and the way on in the message.
    ASSERT_TRUE(fs::exists(out));
    const auto frames = frame_names(out.string());
    ASSERT_FALSE(frames.empty());
    for (const auto& f : frames) EXPECT_EQ(read_doubles(out.string(), "/frames/" + f + "/position").size(), 2u) << f;
    EXPECT_NE(r.err.find("` continues the run and gathers them"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("--restart "), std::string::npos) << r.err;
  } else if (fs::exists(out)) {
    EXPECT_FALSE(frame_names(out.string()).empty());
  }
}

/// After a failed run: continuing in place (no limit now) ends the run and gathers.
void expect_recovery(const fs::path& dir, const fs::path& scene, const fs::path& out) {
  if (!fs::exists(out.string() + ".frames")) return;
  Result r = run_moreau({"run", scene.string(), "--restart", out.string(), "--out", out.string(), "--quiet"}, dir);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_FALSE(fs::exists(out.string() + ".frames"));
  EXPECT_EQ(frame_names(out.string()).back(), "00001000");
}

/// A tmpfs of `size` mounted on `dir` for the object's lifetime; `ok` false when this
/// process may not mount (not root, or a container without the capability).
struct Tmpfs {
  Tmpfs(const fs::path& dir, const std::string& size)
      : dir(dir), ok(::mount("tmpfs", dir.c_str(), "tmpfs", 0, ("size=" + size).c_str()) == 0) {}
  ~Tmpfs() {
    if (ok) ::umount(dir.c_str());
  }
  fs::path dir;
  bool ok;
};

}  // namespace

TEST(WriteFaults, AFileSizeLimitEndsTheRunCleanlyWhereverItStrikes) {
  // Limits that strike at the first file, in the middle of the run (the list of frames),
  // and at the gathering, in memory or (a file too large for memory) by HDF5 on disk.
  struct Case {
    long kb;
    bool on_disk;
  };
  for (const Case c : {Case{1, false}, Case{24, false}, Case{400, false}, Case{400, true}}) {
    const std::string name = std::to_string(c.kb) + (c.on_disk ? "_disk" : "");
    const fs::path dir = scratch_dir("fsize_" + name);
    const fs::path scene = write_file(dir, "scene.json", many_frames_scene());
    const fs::path out = dir / "out.h5";
    Result r = run_limited({"run", scene.string(), "--quiet"}, dir, c.kb, c.on_disk ? "MOREAU_GATHER_IN_MEMORY_MAX=0" : "");
    SCOPED_TRACE("ulimit -f " + name);
    expect_clean_failure(r, dir, out, c.on_disk ? "File too large (it needs about" : "File too large");
    expect_recovery(dir, scene, out);
  }
}

TEST(WriteFaults, AFullDiskEndsTheRunCleanly) {
  for (const char* size : {"2m", "8m"}) {
    const fs::path mnt = scratch_dir(std::string("tmpfs_") + size);
    const Tmpfs disk(mnt, size);
    if (!disk.ok) GTEST_SKIP() << "cannot mount a tmpfs here (needs root)";
    const fs::path work = scratch_dir(std::string("tmpfs_work_") + size);
    const fs::path scene = write_file(work, "scene.json", many_frames_scene(30.0));  // 30000 frames
    const fs::path out = mnt / "out.h5";
    Result r = run_moreau({"run", scene.string(), "--out", out.string(), "--quiet"}, work);
    SCOPED_TRACE(std::string("tmpfs of ") + size);
    expect_clean_failure(r, mnt, out, "No space left on device");
  }
}

TEST(WriteFaults, AFailedCloseOfAnHdf5FileCrashesNothingAfter) {
  // HDF5 1.10 writes cached data and metadata when a file is closed; when that fails,
  // H5Fclose fails and leaves a half-closed file behind, on which the library's exit
  // cleanup crashed (SIGSEGV after "cannot finish writing"). In a child process: a file
  // whose close must fail (a chunk cache to flush past a file-size limit), then more HDF5
  // work, then a normal exit.
  const fs::path dir = scratch_dir("failed_close");
  const std::string path = (dir / "big.h5").string();
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    signal(SIGXFSZ, SIG_IGN);
    struct rlimit limit{64 * 1024, 64 * 1024};
    setrlimit(RLIMIT_FSIZE, &limit);
    namespace h5 = moreau::io::h5;
    h5::Id f = h5::create_on_disk(path);
    const hsize_t n = 100000, chunk = 1000;
    h5::Id space = h5::space(H5Screate_simple(1, &n, nullptr));
    h5::Id dcpl = h5::plist(H5Pcreate(H5P_DATASET_CREATE));
    H5Pset_chunk(dcpl.get(), 1, &chunk);
    std::vector<double> values(n, 1.0);
    {
      h5::Id d = h5::dataset(H5Dcreate2(f.get(), "x", H5T_IEEE_F64LE, space.get(), H5P_DEFAULT, dcpl.get(), H5P_DEFAULT));
      H5Dwrite(d.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data());
    }
    int failed = 0;
    try {
      h5::close_on_disk(f, path);
    } catch (const moreau::RunError& e) {
      failed = std::string(e.what()).find("File too large") != std::string::npos ? 1 : 2;
    }
    h5::MemoryFile other((dir / "after.h5").string());  // the library still works
    h5::write_doubles(other.get(), "y", values.data(), 10, 0);
    other.save((dir / "after.h5").string());
    std::exit(failed == 1 ? 0 : 10 + failed);
  }
  int status = 0;
  waitpid(child, &status, 0);
  ASSERT_TRUE(WIFEXITED(status)) << "the child was killed by signal " << WTERMSIG(status);
  EXPECT_EQ(WEXITSTATUS(status), 0) << "11: the close did not fail; 12: it failed without the OS's reason";
  EXPECT_EQ(read_doubles((dir / "after.h5").string(), "/y").size(), 10u);
}

TEST(WriteFaults, ASecondRunWritingTheSameFileIsRefused) {
  const fs::path dir = scratch_dir("lock");
  const fs::path scene = write_file(dir, "scene.json", many_frames_scene(20.0));
  const std::string out = (dir / "out.h5").string();
  std::string exe = MOREAU_EXE, run = "run", sc = scene.string(), o = "--out", path = out, q = "--quiet";
  char* argv[] = {exe.data(), run.data(), sc.data(), o.data(), path.data(), q.data(), nullptr};
  pid_t first;
  ASSERT_EQ(posix_spawn(&first, MOREAU_EXE, nullptr, nullptr, argv, environ), 0);
  for (int i = 0; i < 500 && !fs::exists(out); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  ASSERT_TRUE(fs::exists(out + ".lock"));
  Result second = run_moreau({"run", scene.string(), "--out", out, "--quiet"}, dir);
  EXPECT_EQ(second.code, 2) << second.err;
  EXPECT_NE(second.err.find("another moreau run (process " + std::to_string(first) + ") is writing this output file"),
            std::string::npos) << second.err;
  Result third = run_moreau({"run", scene.string(), "--restart", out, "--out", out, "--quiet"}, dir);
  EXPECT_NE(third.code, 0);
  // The first run was not disturbed: its folder is its own until it ends.
  EXPECT_TRUE(fs::exists(out + ".frames"));
  kill(first, SIGKILL);  // a killed run's lock goes with it
  int status;
  waitpid(first, &status, 0);
  Result again = run_moreau({"run", scene.string(), "--out", out, "--quiet", "--steps", "50"}, dir);
  EXPECT_EQ(again.code, 0) << again.err;
  EXPECT_FALSE(fs::exists(out + ".lock"));
  EXPECT_FALSE(fs::exists(out + ".frames"));
}
