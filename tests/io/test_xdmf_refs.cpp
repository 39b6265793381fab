// The viewer description (OUT.xmf) is well-formed XML and every array it names exists in
// OUT.h5 with the dimensions and number type it states, so ParaView reads what we say.
#include <gtest/gtest.h>
#include <hdf5.h>

#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>

#include <boost/property_tree/ptree.hpp>
#include <boost/property_tree/xml_parser.hpp>
#include <chrono>
#include <filesystem>
#include <set>
#include <sstream>
#include <thread>

#include "cli_runner.hpp"
#include "display_scenes.hpp"
#include "mixed_scenes.hpp"

extern char** environ;
namespace fs = std::filesystem;
namespace pt = boost::property_tree;
using namespace moreau_test;

namespace {

struct Walk {
  hid_t file;
  std::set<std::string> collections;  // names of the top-level grids
  int items = 0;
  std::vector<std::string> faults;

  /// The XDMF type of an HDF5 dataset, as NumberType/Precision.
  static std::string xdmf_type(const DatasetInfo& i) {
    if (i.type_class == H5T_FLOAT) return "Float" + std::to_string(i.type_size);
    if (i.type_class == H5T_INTEGER) return (i.type_size == 1 ? "Char" : "Int") + std::to_string(i.type_size);
    return "?";
  }

  void item(const pt::ptree& node) {
    const std::string format = node.get("<xmlattr>.Format", "XML");
    if (format != "HDF") return;
    ++items;
    const std::string text = node.get_value<std::string>();
    const std::size_t colon = text.find(':');
    const std::string h5 = text.substr(0, colon), path = text.substr(colon + 1);
    if (h5 != "out.h5") faults.push_back(text + ": not out.h5");
    DatasetInfo i;
    if (!dataset_info(file, path, i)) {
      faults.push_back(path + ": no such dataset");
      return;
    }
    std::istringstream dims(node.get<std::string>("<xmlattr>.Dimensions"));
    std::vector<hsize_t> stated;
    for (hsize_t n; dims >> n;) stated.push_back(n);
    if (stated != i.dims) faults.push_back(path + ": Dimensions differ from the dataset's");
    const std::string type = node.get<std::string>("<xmlattr>.NumberType") + node.get<std::string>("<xmlattr>.Precision");
    if (type != xdmf_type(i)) faults.push_back(path + ": stated " + type + ", dataset is " + xdmf_type(i));
  }

  void visit(const pt::ptree& node) {
    for (const auto& [name, child] : node) {
      if (name == "DataItem") item(child);
      else if (name != "<xmlattr>") visit(child);
    }
  }
};

/// Parses OUT.xmf and checks each HDF DataItem against OUT.h5; returns the collections.
std::set<std::string> check_xdmf(const fs::path& dir) {
  pt::ptree doc;
  EXPECT_NO_THROW(pt::read_xml((dir / "out.xmf").string(), doc)) << "out.xmf is not well-formed XML";
  hid_t f = H5Fopen((dir / "out.h5").string().c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  EXPECT_GE(f, 0);
  Walk w{f};
  const auto& domain = doc.get_child("Xdmf.Domain");
  for (const auto& [name, grid] : domain)
    if (name == "Grid") w.collections.insert(grid.get<std::string>("<xmlattr>.Name"));
  w.visit(doc);
  H5Fclose(f);
  EXPECT_GT(w.items, 0);
  for (const auto& fault : w.faults) ADD_FAILURE() << fault;
  return w.collections;
}

}  // namespace

TEST(Xdmf, NamesOnlyExistingDatasets) {
  for (int d : {2, 3}) {
    const fs::path dir = scratch_dir("xdmf_refs" + std::to_string(d));
    const fs::path scene = write_file(dir, "scene.json", d == 2 ? display_scene_2d() : display_scene_3d());
    const Result res = run_moreau({"run", scene.string(), "--quiet"}, dir);
    ASSERT_EQ(res.code, 0) << res.err;
    EXPECT_EQ(check_xdmf(dir), (std::set<std::string>{"bodies", "shapes", "contacts", "force_network"})) << d << "D";
  }
}

// A scene with rigid bodies and chains (tests/mixed): a grid per modelization (the chain's
// springs as lines over its nodes), the shapes, the contacts and the force network between
// the bodies' reference points.
TEST(Xdmf, MixedScenesDrawEachModelization) {
  for (int d : {2, 3}) {
    const fs::path dir = scratch_dir("xdmf_mixed" + std::to_string(d));
    const fs::path scene = write_file(dir, "scene.json", mixed_scene(d, R"({"type": "auto"})", 0.005, 1));
    const Result res = run_moreau({"run", scene.string(), "--quiet"}, dir);
    ASSERT_EQ(res.code, 0) << res.err;
    EXPECT_EQ(check_xdmf(dir), (std::set<std::string>{"rigid", "chain", "shapes", "contacts", "force_network"}))
        << d << "D";
  }
}

// Continuing a file (restart into the same output) lists the old frames again, from what
// they hold.
TEST(Xdmf, NamesOnlyExistingDatasetsAfterContinuing) {
  const fs::path dir = scratch_dir("xdmf_refs_restart");
  const fs::path scene = write_file(dir, "scene.json", display_scene_3d());
  ASSERT_EQ(run_moreau({"run", scene.string(), "--quiet"}, dir).code, 0);
  const Result res = run_moreau({"run", scene.string(), "--restart", "out.h5", "--frame", "5", "--out", "out.h5",
                                 "--steps", "10", "--quiet"},
                                dir);
  ASSERT_EQ(res.code, 0) << res.err;
  EXPECT_EQ(check_xdmf(dir), (std::set<std::string>{"bodies", "shapes", "contacts", "force_network"}));
}

TEST(Xdmf, PointsDisplayHasNoShapesGrid) {
  const fs::path dir = scratch_dir("xdmf_points");
  const fs::path scene = write_file(dir, "scene.json", display_scene_2d("points"));
  ASSERT_EQ(run_moreau({"run", scene.string(), "--quiet"}, dir).code, 0);
  EXPECT_EQ(check_xdmf(dir), (std::set<std::string>{"bodies", "contacts", "force_network"}));
}

// Killed mid-run, OUT.h5 links /display and its frames into OUT.h5.frames/: the pair still
// reads as one file and the description names only what it holds.
TEST(Xdmf, NamesOnlyExistingDatasetsAfterSigkill) {
  const fs::path dir = scratch_dir("xdmf_kill");
  std::ostringstream s;
  s << R"({"format": "moreau-scene/1", "dimension": 3, "time": {"step": 0.001, "duration": 100},
  "gravity": [0, 0, -9.81], "materials": {"m": {"density": 1000}}, "output": {"every": 1}, "bodies": [)";
  for (int i = 0; i < 2000; ++i)
    s << (i ? "," : "") << R"({"name": "s)" << i << R"(", "material": "m", "position": [)" << i % 50 << ", "
      << i / 50 << R"(, 0], "contactors": [{"shape": "sphere", "radius": 0.3}]})";
  s << "]}";
  const fs::path scene = write_file(dir, "scene.json", s.str());
  std::string exe = MOREAU_EXE, run = "run", sc = scene.string(), o = "--out", path = (dir / "out.h5").string(),
              q = "--quiet";
  char* argv[] = {exe.data(), run.data(), sc.data(), o.data(), path.data(), q.data(), nullptr};
  pid_t pid;
  ASSERT_EQ(posix_spawn(&pid, MOREAU_EXE, nullptr, nullptr, argv, environ), 0);
  // Until a few frames are listed (the description is rewritten at 1, 2, 4, 8 frames).
  for (int i = 0; i < 600 && !fs::exists(dir / "out.h5.frames" / "00000008.h5"); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  kill(pid, SIGKILL);
  int status;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status)) << "the run ended before the kill";
  ASSERT_TRUE(fs::exists(dir / "out.h5.frames" / "display.h5"));
  EXPECT_EQ(check_xdmf(dir), (std::set<std::string>{"bodies", "shapes"}));
  fs::remove_all(dir);
}
