// Shadow solvers (MOREAU_SHADOW_SOLVERS, docs/solvers.md "Comparing solvers on one run"):
// every problem of the run is solved also by each shadow, from the same warm start, and
// the run keeps the scene solver's answers: its output is bit-identical to the run
// without shadows, and the table counts one solve per solver per solve of the scene's.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>

#include "cli_runner.hpp"
#include "h5_read.hpp"

namespace fs = std::filesystem;
using namespace moreau_test;

namespace {

/// Sets environment variables for the runs of one test (the runner passes the
/// environment on), and unsets them after.
struct Environment {
  std::vector<std::string> names;
  void set(const std::string& name, const std::string& value) {
    setenv(name.c_str(), value.c_str(), 1);
    names.push_back(name);
  }
  ~Environment() {
    for (const auto& n : names) unsetenv(n.c_str());
  }
};

/// The first 60 steps of an example scene (a brick wall on a floor, 224 contacts), written
/// as a scene whose `solver` block is `solver`.
fs::path scene_with(const fs::path& dir, const nlohmann::json& solver) {
  std::ifstream in(std::string(MOREAU_SOURCE_DIR) + "/configs/brick_wall_2d.json");
  nlohmann::json s = nlohmann::json::parse(in);
  s["solver"] = solver;
  s["time"]["duration"] = 0.06;  // 60 steps
  s["output"] = {{"file", "out.h5"}, {"every", 20}};
  return write_file(dir, "scene.json", s.dump());
}

/// Every dataset under /frames of both files holds the same values, bit for bit.
void expect_same_frames(const std::string& a, const std::string& b) {
  const auto names = datasets_under(a, "/frames");
  ASSERT_EQ(names, datasets_under(b, "/frames"));
  ASSERT_GT(names.size(), 30u);
  for (const auto& n : names) {
    const auto x = read_doubles(a, "/frames/" + n), y = read_doubles(b, "/frames/" + n);
    ASSERT_EQ(x.size(), y.size()) << n;
    for (std::size_t i = 0; i < x.size(); ++i) ASSERT_EQ(x[i], y[i]) << n << "[" << i << "] differs";
  }
  for (const char* f : {"00000020", "00000060"})
    for (const char* attr : {"error", "iterations"})
      EXPECT_EQ(read_attribute(a, std::string("/frames/") + f + "/solver", attr),
                read_attribute(b, std::string("/frames/") + f + "/solver", attr));
}

/// Runs the scene without and with the shadows; checks the outputs and the table.
void check_shadows(const std::string& name, const nlohmann::json& solver, const nlohmann::json& shadows,
                   const std::vector<std::string>& labels) {
  const fs::path dir = scratch_dir(name);
  const fs::path scene = scene_with(dir, solver);
  const Result plain = run_moreau({"run", scene.string(), "--out", "plain.h5"}, dir);
  ASSERT_EQ(plain.code, 0) << plain.err;
  // The identity below is not because every solver gives the same answers: the first
  // shadow as the scene's solver makes another run.
  nlohmann::json other = shadows[0].is_string() ? nlohmann::json{{"type", shadows[0]}} : shadows[0];
  if (!other.contains("tolerance")) other["tolerance"] = solver["tolerance"];
  fs::create_directories(dir / "other");
  const fs::path other_scene = scene_with(dir / "other", other);
  ASSERT_EQ(run_moreau({"run", other_scene.string(), "--out", "other.h5", "--quiet"}, dir / "other").code, 0);
  EXPECT_NE(read_doubles((dir / "plain.h5").string(), "/frames/00000060/position"),
            read_doubles((dir / "other" / "other.h5").string(), "/frames/00000060/position"));
  Environment env;
  env.set("MOREAU_SHADOW_SOLVERS", shadows.dump());
  env.set("MOREAU_SHADOW_REPORT", (dir / "shadow.json").string());
  const Result r = run_moreau({"run", scene.string(), "--out", "shadow.h5"}, dir);
  ASSERT_EQ(r.code, 0) << r.err;
  expect_same_frames((dir / "plain.h5").string(), (dir / "shadow.h5").string());

  // The run's own count of solves (the end-of-run summary) is every row's.
  std::smatch m;
  ASSERT_TRUE(std::regex_search(r.err, m, std::regex("contact solves: (?:\\d+ of )?(\\d+) steps"))) << r.err;
  const long solves = std::stol(m[1]);
  EXPECT_EQ(solves, 60);
  EXPECT_NE(r.err.find("(shadows, not counted)"), std::string::npos) << r.err;
  const auto table = r.out.find("solvers on the same problems");
  ASSERT_NE(table, std::string::npos) << r.out;
  for (const auto& label : labels)
    EXPECT_TRUE(std::regex_search(r.out.substr(table), std::regex("\\n  " + label + " +" + std::to_string(solves) + " ")))
        << label << " with " << solves << " solves:\n" << r.out;

  std::ifstream in(dir / "shadow.json");
  const nlohmann::json report = nlohmann::json::parse(in);
  EXPECT_EQ(report["format"], "moreau-shadow-solvers/1");
  EXPECT_EQ(report["steps"], 60);
  const auto& rows = report["solvers"];
  ASSERT_EQ(rows.size(), labels.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    EXPECT_EQ(rows[i]["label"], labels[i]);
    EXPECT_EQ(rows[i]["role"], i == 0 ? "scene" : "shadow");
    EXPECT_EQ(rows[i]["solves"], solves);
    EXPECT_GT(rows[i]["iterations"].get<long>(), 0) << labels[i];
    EXPECT_GT(rows[i]["cpu_seconds"].get<double>(), 0.0) << labels[i];
    // A shadow that is the scene's solver again (same block) sees the same problems from
    // the same warm starts, and keeps its own state as the scene's does: the same reports.
    if (i > 0 && rows[i]["solver"] == rows[0]["solver"])
      for (const char* k : {"iterations", "misses", "worst_error", "worst_solve", "work"})
        EXPECT_EQ(rows[i][k], rows[0][k]) << labels[i] << " " << k;
  }
  // A shadow without `tolerance` takes the scene solver's; one with it keeps its own.
  for (std::size_t i = 1; i < rows.size(); ++i)
    EXPECT_EQ(rows[i]["solver"]["tolerance"], shadows[i - 1].is_object() && shadows[i - 1].contains("tolerance")
                                                  ? shadows[i - 1]["tolerance"]
                                                  : rows[0]["solver"]["tolerance"]);
}

}  // namespace

TEST(ShadowSolvers, AutoWithShadowsThatReadWKeepsTheOutputBitIdentical) {
  // `auto` works on the factor (no W); nlgs with exchange "w" reads W, which is assembled
  // for it and taken away again; apgd works on the factor as `auto` does; a second `auto`
  // has its own memory.
  check_shadows("shadow_auto", {{"type", "auto"}, {"tolerance", 1e-3}},
                {{{"type", "nlgs"}, {"exchange", "w"}}, {{"type", "apgd"}, {"tolerance", 1e-4}}, "auto"},
                {"auto", "nlgs", "apgd", "auto #2"});
}

TEST(ShadowSolvers, SceneSolverReadingWWithShadowsOnTheFactorKeepsTheOutputBitIdentical) {
  check_shadows("shadow_nlgs_w", {{"type", "nlgs"}, {"exchange", "w"}, {"tolerance", 1e-3}},
                {"apgd", "auto", {{"type", "nlgs"}, {"exchange", "w"}}}, {"nlgs", "apgd", "auto", "nlgs #2"});
}

TEST(ShadowSolvers, BadShadowListsAreInputErrorsNamingTheVariable) {
  const fs::path dir = scratch_dir("shadow_bad");
  const fs::path scene = scene_with(dir, {{"type", "auto"}});
  Environment env;
  env.set("MOREAU_SHADOW_SOLVERS", R"([{"type": "nlgz"}])");
  Result r = run_moreau({"run", scene.string(), "--steps", "2"}, dir);
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("MOREAU_SHADOW_SOLVERS (environment variable): at /0/type: unknown solver 'nlgz'"), std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("admm, apgd, auto"), std::string::npos) << r.err;  // the valid names
  env.set("MOREAU_SHADOW_SOLVERS", R"([{"type": "nlgs")");
  r = run_moreau({"run", scene.string(), "--steps", "2"}, dir);
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("MOREAU_SHADOW_SOLVERS (environment variable): expected a JSON array"), std::string::npos) << r.err;
  env.set("MOREAU_SHADOW_SOLVERS", R"([{"type": "apgd", "on_failure": "stop"}])");
  r = run_moreau({"run", scene.string(), "--steps", "2"}, dir);
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("at /0/on_failure: unknown key"), std::string::npos) << r.err;
  env.set("MOREAU_SHADOW_SOLVERS", R"(["apgd"])");
  env.set("MOREAU_SHADOW_REPORT", (dir / "no_such_folder" / "r.json").string());
  r = run_moreau({"run", scene.string(), "--steps", "2"}, dir);
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("MOREAU_SHADOW_REPORT (environment variable): no folder"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "out.h5")) << "checked before the run";
}
