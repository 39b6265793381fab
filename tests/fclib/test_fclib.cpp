// FCLib problems: the shared files read as h5dump shows them, malformed files refused
// with the HDF5 path of the fault, and `moreau fclib solve` end to end.
#include <gtest/gtest.h>
#include <hdf5.h>

#include <filesystem>
#include <Eigen/Dense>
#include <moreau/contact_error.hpp>
#include <moreau/error.hpp>
#include <nlohmann/json.hpp>

#include "cli_runner.hpp"
#include "h5_read.hpp"
#include "h5_write.hpp"
#include "kernel/fclib/fclib.hpp"

namespace fs = std::filesystem;
using namespace moreau_test;

namespace {

std::string shared(const std::string& name) { return std::string(MOREAU_SHARED_DIR) + "/fclib/" + name; }

/// Writes a small local problem file with the given layout, optionally broken.
std::string write_local(const std::string& name, const std::string& fault) {
  const fs::path dir = scratch_dir("fclib_files");
  const std::string path = (dir / name).string();
  hid_t f = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  auto ints = [&](const char* p, std::vector<int> v) { h5_write(f, p, v); };
  auto dbls = [&](const char* p, std::vector<double> v) { h5_write(f, p, v); };
  hid_t lcpl = H5Pcreate(H5P_LINK_CREATE);
  H5Pset_create_intermediate_group(lcpl, 1);
  H5Gclose(H5Gcreate2(f, "/fclib_local/W", lcpl, H5P_DEFAULT, H5P_DEFAULT));
  H5Gclose(H5Gcreate2(f, "/fclib_local/vectors", lcpl, H5P_DEFAULT, H5P_DEFAULT));
  H5Pclose(lcpl);
  // One 3D contact, W = diag(2, 3, 3) as a triplet matrix; q pushes into contact.
  ints("/fclib_local/spacedim", {3});
  ints("/fclib_local/W/m", {3});
  ints("/fclib_local/W/n", {fault == "dims" ? 4 : 3});
  ints("/fclib_local/W/nz", {3});
  ints("/fclib_local/W/nzmax", {3});
  ints("/fclib_local/W/i", {0, 1, fault == "index" ? 7 : 2});
  ints("/fclib_local/W/p", {0, 1, 2});
  dbls("/fclib_local/W/x", {2, 3, 3});
  if (fault != "no_q") dbls("/fclib_local/vectors/q", {-1, 0.5, 0});
  dbls("/fclib_local/vectors/mu", {fault == "mu" ? -0.3 : 0.3});
  H5Fclose(f);
  return path;
}

std::string fault_of(const std::string& path) {
  try {
    moreau::fclib::read(path);
  } catch (const moreau::InputError& e) {
    return e.describe();
  }
  return "(no error)";
}

}  // namespace

TEST(Fclib, ReadsTheSharedProblems) {
  struct Expect {
    const char* file;
    bool global;
    int contacts;
  };
  for (auto e : {Expect{"fclib-local_problem_test.hdf5", false, 48}, Expect{"faf-Capsules-i97-269.hdf5", false, 216},
                 Expect{"faf-Box_Stacks-i0035-31-0.hdf5", true, 31}, Expect{"spheres-in-a-box-98-i10000-256-10.hdf5", true, 256},
                 Expect{"CubeH8.hdf5", true, 1}}) {
    auto p = moreau::fclib::read(shared(e.file));
    EXPECT_EQ(p.global, e.global) << e.file;
    EXPECT_EQ(p.local.contacts(), e.contacts) << e.file;
    EXPECT_EQ(p.local.W.rows(), 3 * e.contacts) << e.file;
    EXPECT_EQ(p.local.q.size(), 3 * e.contacts) << e.file;
  }
  // Capsules: W in CSR with 8586 stored entries (h5dump: /fclib_local/W/x is {8586}).
  EXPECT_EQ(moreau::fclib::read(shared("faf-Capsules-i97-269.hdf5")).local.W.nonZeros(), 8586);
  // Box stacks (global, triplets): H has 485 entries, M 450 (diagonal).
  auto box = moreau::fclib::read(shared("faf-Box_Stacks-i0035-31-0.hdf5"));
  EXPECT_EQ(box.global_problem.H.nonZeros(), 485);
  EXPECT_EQ(box.global_problem.M.rows(), 450);
}

TEST(Fclib, ReductionOfAGlobalProblemMatchesItsDefinition) {
  // CubeH8 has a full (finite-element) M: W = Hᵀ M⁻¹ H through a sparse Cholesky.
  auto p = moreau::fclib::read(shared("CubeH8.hdf5"));
  const auto& g = p.global_problem;
  Eigen::MatrixXd M(g.M), H(g.H);
  Eigen::MatrixXd W = H.transpose() * M.ldlt().solve(H);
  EXPECT_TRUE(Eigen::MatrixXd(p.local.W).isApprox(W, 1e-10));
  Eigen::VectorXd q = g.w + H.transpose() * M.ldlt().solve(g.f);
  EXPECT_TRUE(p.local.q.isApprox(q, 1e-10));
}

TEST(Fclib, MalformedFilesNameTheHdf5PathOfTheFault) {
  EXPECT_NE(fault_of(write_local("index.hdf5", "index")).find("at /fclib_local/W/i: entry 2 = 7.000000 is not an index below 3"),
            std::string::npos) << fault_of(write_local("index.hdf5", "index"));
  EXPECT_NE(fault_of(write_local("dims.hdf5", "dims")).find("at /fclib_local/W: the matrix is 3x4, expected 3x3"), std::string::npos);
  EXPECT_NE(fault_of(write_local("mu.hdf5", "mu")).find("at /fclib_local/vectors/mu: friction coefficient 0 is -0.3"),
            std::string::npos);
  EXPECT_NE(fault_of(write_local("no_q.hdf5", "no_q")).find("at /fclib_local/vectors/q: missing dataset"), std::string::npos);
  // Truncated: the first kilobyte of a real file.
  const fs::path dir = scratch_dir("fclib_trunc");
  fs::copy_file(shared("faf-Capsules-i97-269.hdf5"), dir / "t.hdf5");
  fs::resize_file(dir / "t.hdf5", 1024);
  EXPECT_NE(fault_of((dir / "t.hdf5").string()).find("cannot open as an HDF5 file"), std::string::npos);
}

TEST(Fclib, SolveCommandPrintsOneJsonLineAndWritesTheSolution) {
  const std::string path = write_local("good.hdf5", "");
  const fs::path dir = fs::path(path).parent_path();
  Result r = run_moreau({"fclib", "solve", path, "--solver", "nlgs", "--tol", "1e-10", "--solution", "sol.hdf5"}, dir);
  ASSERT_EQ(r.code, 0) << r.err;
  auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["kind"], "local");
  EXPECT_EQ(j["contacts"], 1);
  EXPECT_EQ(j["converged"], true);
  EXPECT_LE(j["error"].get<double>(), 1e-10);
  // Analytic: q_n = −1 closes the contact, r_n = 1/2. Sticking would need r_t = −0.5/3,
  // beyond μ r_n = 0.15: it slides, r_t = −0.15, u_t = 3(−0.15) + 0.5 = 0.05 > 0.
  const auto sol = read_doubles((dir / "sol.hdf5").string(), "/solution/r");
  EXPECT_NEAR(sol[0], 0.5, 1e-12);
  EXPECT_NEAR(sol[1], -0.15, 1e-12);
  EXPECT_NEAR(sol[2], 0.0, 1e-12);
  // The keys come in the order of DESIGN §3.1.
  EXPECT_EQ(r.out.rfind("{\"problem\":", 0), 0u) << r.out;
  Result bad = run_moreau({"fclib", "solve", write_local("mu2.hdf5", "mu")}, dir);
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.err.find("/fclib_local/vectors/mu"), std::string::npos);
}

TEST(Fclib, NlgsOnTheSharedLocalProblemsReportsAnHonestError) {
  for (const char* f : {"faf-Capsules-i97-269.hdf5", "fclib-local_problem_test.hdf5"}) {
    Result r = run_moreau({"fclib", "solve", shared(f), "--solver", "nlgs", "--tol", "1e-4", "--max-iter", "100000"});
    ASSERT_EQ(r.code, 0) << r.err;
    auto j = nlohmann::json::parse(r.out);
    auto p = moreau::fclib::read(shared(f));
    EXPECT_TRUE(j["converged"].get<bool>()) << r.out;
    EXPECT_LE(j["error"].get<double>(), 1e-4) << r.out;
  }
}

TEST(Fclib, SolveRepeatReportsTheRepeatCount) {
  const std::string path = write_local("repeat.hdf5", "");
  Result r = run_moreau({"fclib", "solve", path, "--solver", "nlgs", "--tol", "1e-10", "--repeat", "3"});
  ASSERT_EQ(r.code, 0) << r.err;
  auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["repeats"], 3);
  EXPECT_EQ(j["converged"], true);
  EXPECT_GE(j["seconds"].get<double>(), 0.0);
  EXPECT_GT(j["work"].get<double>(), 0.0);  // nlgs counts its sweeps and checks
  // Only keys added to DESIGN §3.1's line: the first ones keep their order.
  EXPECT_EQ(r.out.rfind("{\"problem\":", 0), 0u) << r.out;
  EXPECT_EQ(run_moreau({"fclib", "solve", path, "--repeat", "0"}).code, 2);
}

TEST(Fclib, SolveParamSetsSchemaParametersAndRefusesUnknownOnes) {
  const std::string path = write_local("param.hdf5", "");
  Result ok = run_moreau({"fclib", "solve", path, "--solver", "nlgs", "--param", "relaxation=0.9", "--param",
                          "tolerance=1e-9"});
  ASSERT_EQ(ok.code, 0) << ok.err;
  EXPECT_DOUBLE_EQ(nlohmann::json::parse(ok.out)["tolerance"].get<double>(), 1e-9);
  // A value that is not JSON is a string: the schema then checks it like a scene value.
  Result str = run_moreau({"fclib", "solve", path, "--solver", "nlgs", "--param", "relaxation=fast"});
  EXPECT_EQ(str.code, 2);
  EXPECT_NE(str.err.find("/relaxation"), std::string::npos) << str.err;

  Result bad = run_moreau({"fclib", "solve", path, "--solver", "nlgs", "--param", "nonsense=1"});
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.err.find("unknown key \"nonsense\""), std::string::npos) << bad.err;
  EXPECT_NE(bad.err.find("relaxation"), std::string::npos) << "the valid keys are listed: " << bad.err;
  EXPECT_EQ(bad.out, "");

  EXPECT_EQ(run_moreau({"fclib", "solve", path, "--solver", "nlgs", "--param", "novalue"}).code, 2);
  EXPECT_EQ(run_moreau({"fclib", "solve", path, "--param", "tolerance=1e-6", "--tol", "1e-6"}).code, 2);
}
