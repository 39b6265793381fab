// A run killed by SIGKILL at any moment leaves an output file that opens, in which every
// visible frame is complete (every dataset present, of the right size, readable).
#include <gtest/gtest.h>
#include <hdf5.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>

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

}  // namespace

TEST(Kill, EveryVisibleFrameIsCompleteAfterSigkill) {
  const fs::path dir = scratch_dir("kill");
  const fs::path scene = write_file(dir, "scene.json", many_bodies_scene());
  int kills = 0, nonempty = 0;
  for (int k = 0; k < 24; ++k) {
    const fs::path out = dir / ("out" + std::to_string(k) + ".h5");
    std::string exe = MOREAU_EXE, run = "run", sc = scene.string(), o = "--out", path = out.string(), q = "--quiet";
    char* argv[] = {exe.data(), run.data(), sc.data(), o.data(), path.data(), q.data(), nullptr};
    pid_t pid;
    ASSERT_EQ(posix_spawn(&pid, MOREAU_EXE, nullptr, nullptr, argv, environ), 0);
    // Varied moments: before the file exists, during the first frames, later.
    std::this_thread::sleep_for(std::chrono::milliseconds(40 + 37 * k));
    kill(pid, SIGKILL);
    int status;
    waitpid(pid, &status, 0);
    ASSERT_TRUE(WIFSIGNALED(status)) << "the run ended before the kill";
    ++kills;
    fs::remove(fs::path(out.string() + ".part"));  // killed while creating it: never under the output name
    if (!fs::exists(out)) continue;
    std::string fault;
    const int frames = check_complete(out.string(), fault);
    EXPECT_GE(frames, 0) << out << ": " << fault;
    EXPECT_TRUE(fault.empty()) << out << ": " << fault;
    if (frames > 0) ++nonempty;
    fs::remove(out);  // frames are large: keep the disk clean as we go
  }
  EXPECT_EQ(kills, 24);
  EXPECT_GE(nonempty, 12) << "most kills should land after frames were written";
  fs::remove_all(dir);
  std::cout << "killed " << kills << " runs; " << nonempty << " files had frames, all complete\n";
}
