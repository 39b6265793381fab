// Bad input of elastic (finite-element) bodies: exit code 2, the file and the JSON pointer
// or the mesh file's line, and the element's number (issue 12, Meshes).
#include <gtest/gtest.h>

#include <filesystem>

#include "cli_runner.hpp"

namespace fs = std::filesystem;
using namespace moreau_test;

namespace {

std::string elastic_scene(const std::string& mesh, const std::string& material, const std::string& extra = "") {
  return R"({"format": "moreau-scene/1", "dimension": 2, "time": {"step": 0.01, "duration": 0.1},
  "materials": {"m": )" + material + R"(},
  "bodies": [{"name": "d", "model": "elastic", "material": "m", "mesh": )" + mesh + extra + R"(}]})";
}

const std::string kGood = R"({"density": 1000, "young": 1e6, "poisson": 0.3})";
const std::string kDisk = R"({"generate": "disk", "centre": [0, 0], "radius": 0.1, "size": 0.02})";

/// `moreau check` and `moreau run` exit 2 with every piece of `expected` in the message.
void expect_bad(const std::string& name, const std::string& scene, const std::vector<std::string>& expected,
                const std::string& msh = "") {
  const fs::path dir = scratch_dir(name);
  if (!msh.empty()) write_file(dir, "mesh.msh", msh);
  const fs::path path = write_file(dir, "scene.json", scene);
  for (const char* cmd : {"check", "run"}) {
    Result r = run_moreau({cmd, path.string()}, dir);
    EXPECT_EQ(r.code, 2) << cmd << ": " << r.err;
    for (const auto& e : expected) EXPECT_NE(r.err.find(e), std::string::npos) << cmd << ": expected " << e << "\ngot: " << r.err;
  }
  EXPECT_FALSE(fs::exists(dir / "out.h5"));
}

}  // namespace

TEST(ElasticErrors, MissingMeshFile) {
  expect_bad("fe_missing", elastic_scene(R"({"file": "nowhere.msh"})", kGood),
             {"/bodies/0/mesh/file", "nowhere.msh", "cannot open"});
}

TEST(ElasticErrors, MalformedMeshFileNamesTheLine) {
  expect_bad("fe_malformed", elastic_scene(R"({"file": "mesh.msh"})", kGood), {"mesh.msh:7", "node 2"},
             "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n3\n1 0 0 0\n2 1 0 x\n");
}

TEST(ElasticErrors, DegenerateElementNamesItsNumberAndLine) {
  expect_bad("fe_degenerate", elastic_scene(R"({"file": "mesh.msh"})", kGood), {"element 9", "mesh.msh:14", "degenerate"},
             "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 2 0 0\n$EndNodes\n"
             "$Elements\n2\n7 2 2 1 1 1 2 3\n9 2 2 1 1 1 2 4\n$EndElements\n");
}

TEST(ElasticErrors, IncompressibleOrNonPositiveMaterial) {
  expect_bad("fe_nu", elastic_scene(kDisk, R"({"density": 1000, "young": 1e6, "poisson": 0.5})"),
             {"/materials/m/poisson", "0.5"});
  expect_bad("fe_young", elastic_scene(kDisk, R"({"density": 1000, "young": 0, "poisson": 0.3})"), {"/materials/m/young"});
  expect_bad("fe_no_young", elastic_scene(kDisk, R"({"density": 1000})"), {"young"});
}

TEST(ElasticErrors, UnknownGroupListsTheValidOnes) {
  expect_bad("fe_group", elastic_scene(kDisk, kGood, R"(, "fixed": ["bottom"])"), {"/bodies/0/fixed/0", "\"bottom\"", "\"boundary\""});
  expect_bad("fe_generator", elastic_scene(R"({"generate": "ring", "size": 0.1})", kGood),
             {"/bodies/0/mesh/generate", "rectangle, disk, box"});
}
