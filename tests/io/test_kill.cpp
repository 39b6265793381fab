// A run killed by SIGKILL at any moment leaves an output file that opens, in which every
// visible frame is complete (every dataset present, of the right size, readable).
#include <gtest/gtest.h>
#include <hdf5.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <sstream>
#include <thread>

#include "cli_runner.hpp"

extern char** environ;
namespace fs = std::filesystem;
using namespace moreau_test;

namespace {

/// 5000 bodies in flight, a frame every step: frames take long enough to write that
/// kills land inside them.
std::string many_bodies_scene() {
  std::ostringstream s;
  s << R"({"format": "moreau-scene/1", "dimension": 3, "time": {"step": 0.001, "duration": 100},
  "gravity": [0, 0, -9.81], "output": {"every": 1}, "bodies": [)";
  for (int i = 0; i < 5000; ++i)
    s << (i ? "," : "") << "{\"name\": \"b" << i << "\", \"position\": [" << i << ", 0, 0], \"mass\": 1, "
      << "\"inertia\": [1, 2, 3], \"angular_velocity\": [0.1, 0.2, 0.3]}";
  s << "]}";
  return s.str();
}

/// Opens the file and reads every dataset of every frame; returns the number of frames.
int check_complete(const std::string& path, std::string& fault) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (f < 0) {
    fault = "cannot open";
    return -1;
  }
  hid_t g = H5Gopen2(f, "/frames", H5P_DEFAULT);
  if (g < 0) {
    fault = "no /frames group";
    H5Fclose(f);
    return -1;
  }
  H5G_info_t info;
  H5Gget_info(g, &info);
  int frames = 0;
  for (hsize_t i = 0; i < info.nlinks; ++i) {
    char name[32];
    H5Lget_name_by_idx(g, ".", H5_INDEX_NAME, H5_ITER_INC, i, name, sizeof name, H5P_DEFAULT);
    for (const char* ds : {"position", "velocity", "orientation", "angular_velocity"}) {
      const std::string p = std::string("/frames/") + name + "/" + ds;
      hid_t d = H5Dopen2(f, p.c_str(), H5P_DEFAULT);
      if (d < 0) {
        fault = "missing " + p;
        break;
      }
      hid_t sp = H5Dget_space(d);
      const hssize_t n = H5Sget_simple_extent_npoints(sp);
      std::vector<double> v(n);
      const bool ok = n == 5000 * (std::string(ds) == "orientation" ? 4 : 3) &&
                      H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()) >= 0;
      H5Sclose(sp);
      H5Dclose(d);
      if (!ok) fault = "unreadable " + p;
    }
    ++frames;
  }
  H5Gclose(g);
  H5Fclose(f);
  return frames;
}

/// The number of frames OUT.h5 lists now (-1 while it does not exist). The file is never
/// modified in place (a new list is renamed over it), so reading it during the run is safe.
int listed_frames(const fs::path& out) {
  if (!fs::exists(out)) return -1;
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  hid_t f = H5Fopen(out.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (f < 0) return -1;
  int n = -1;
  hid_t g = H5Gopen2(f, "/frames", H5P_DEFAULT);
  if (g >= 0) {
    H5G_info_t info;
    if (H5Gget_info(g, &info) >= 0) n = static_cast<int>(info.nlinks);
    H5Gclose(g);
  }
  H5Fclose(f);
  return n;
}

bool has_part_file(const fs::path& folder) {
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(folder, ec))
    if (e.path().extension() == ".part") return true;
  return false;
}

/// A moment to kill a run at: once OUT.h5 lists at least `listed` frames, when `event` is
/// next seen. The temporary files last a moment only and a poll may miss them: once the
/// list has grown past what it held when the wait began, the moment has passed and the kill
/// lands at once.
struct Moment {
  enum Event { spawned, folder, frame_part, list_part, now } event;
  int listed = 0;
  std::string what() const {
    static const char* names[] = {"its start", "the frames folder", "a frame being written", "the list being rewritten",
                                  "the list"};
    return std::string(names[event]) + " with " + std::to_string(listed) + " frames listed";
  }
};

std::vector<Moment> kill_moments() {
  std::vector<Moment> m = {{Moment::spawned, 0}, {Moment::folder, 0}, {Moment::frame_part, 0},
                           {Moment::list_part, 0}, {Moment::now, 1}};
  for (int n = 1; n <= 6; ++n) {
    m.push_back({Moment::frame_part, n});
    m.push_back({Moment::list_part, n});
    m.push_back({Moment::now, n + 1});
  }
  m.push_back({Moment::now, 8});
  return m;  // 24 kills, 20 of them after a listed frame was seen
}

/// What the test saw of the run before it killed it.
struct Seen {
  bool reached = false;  // the moment was reached (not the time limit, not the end of the run)
  int listed = 0;        // frames OUT.h5 listed at the last look
};

/// Only a run that hangs reaches this: it bounds the test, it does not time the kills.
constexpr std::chrono::seconds wait_limit{600};

Seen wait_for(const Moment& when, pid_t pid, const fs::path& out, const fs::path& folder) {
  Seen seen;
  if (when.event == Moment::spawned) {
    seen.reached = true;
    return seen;
  }
  const auto give_up = std::chrono::steady_clock::now() + wait_limit;
  int at_start = -1;  // the list when the wait for the event began
  while (std::chrono::steady_clock::now() < give_up) {
    siginfo_t info{};
    if (waitid(P_PID, static_cast<id_t>(pid), &info, WEXITED | WNOHANG | WNOWAIT) == 0 && info.si_pid == pid)
      return seen;  // ended: the caller's waitpid reports how
    const int n = listed_frames(out);
    seen.listed = std::max(seen.listed, n);
    if (n >= when.listed) {
      if (at_start < 0) at_start = std::max(n, 0);
      // Looked for last, so that the kill follows the event as closely as the poll can.
      bool event = true;
      if (when.event == Moment::folder) event = fs::exists(folder);
      if (when.event == Moment::frame_part) event = has_part_file(folder);
      if (when.event == Moment::list_part) event = fs::exists(out.string() + ".part");
      if (event || n > at_start) {
        seen.reached = true;
        return seen;
      }
    }
    std::this_thread::sleep_for(std::chrono::microseconds(300));
  }
  return seen;
}

}  // namespace

TEST(Kill, EveryVisibleFrameIsCompleteAfterSigkill) {
  // The kills land at moments defined by what the test sees of the run (a folder, a
  // temporary file, the number of frames OUT.h5 lists), never by wall-clock delays, so
  // that the load of the machine changes when they land, not what is checked.
  const fs::path dir = scratch_dir("kill");
  const fs::path scene = write_file(dir, "scene.json", many_bodies_scene());
  const std::vector<Moment> moments = kill_moments();
  int kills = 0, nonempty = 0;
  for (std::size_t k = 0; k < moments.size(); ++k) {
    const Moment& when = moments[k];
    const fs::path out = dir / ("out" + std::to_string(k) + ".h5");
    const fs::path folder = out.string() + ".frames";
    std::string exe = MOREAU_EXE, run = "run", sc = scene.string(), o = "--out", path = out.string(), q = "--quiet";
    char* argv[] = {exe.data(), run.data(), sc.data(), o.data(), path.data(), q.data(), nullptr};
    pid_t pid;
    ASSERT_EQ(posix_spawn(&pid, MOREAU_EXE, nullptr, nullptr, argv, environ), 0);
    const Seen seen = wait_for(when, pid, out, folder);
    kill(pid, SIGKILL);
    int status;
    waitpid(pid, &status, 0);
    ASSERT_TRUE(WIFSIGNALED(status)) << "the run ended before kill " << k;
    ASSERT_TRUE(seen.reached) << "kill " << k << ": the run did not reach " << when.what() << " within "
                              << wait_limit.count() << " s";
    ++kills;
    fs::remove(fs::path(out.string() + ".part"));  // killed while writing the list: never under the output name
    // A frame the test saw listed before the kill is still listed after it: the list is
    // replaced by a rename, never emptied or cut.
    if (seen.listed > 0) EXPECT_TRUE(fs::exists(out)) << "kill " << k << " (" << when.what() << "): " << out
                                                      << " listed " << seen.listed << " frames before the kill and is gone";
    if (fs::exists(out)) {
      std::string fault;
      const int frames = check_complete(out.string(), fault);
      EXPECT_GE(frames, seen.listed) << "kill " << k << " (" << when.what() << "): " << out << ": " << fault;
      EXPECT_TRUE(fault.empty()) << "kill " << k << " (" << when.what() << "): " << out << ": " << fault;
      if (frames > 0) ++nonempty;
    }
    // Frames are large: keep the disk clean as we go.
    fs::remove(out);
    fs::remove_all(folder);
  }
  EXPECT_EQ(kills, static_cast<int>(moments.size()));
  // Each of the 20 moments after a listed frame was reached before its kill (asserted
  // above), and its file kept at least the frames seen: at least 20 files with frames.
  EXPECT_GE(nonempty, 20);
  fs::remove_all(dir);
  std::cout << "killed " << kills << " runs; " << nonempty << " files had frames, all complete\n";
}
