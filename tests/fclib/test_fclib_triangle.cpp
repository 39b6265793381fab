// Global FCLib problems whose symmetric mass matrix is stored as one triangle (LMGC90's
// symmetric storage, e.g. the shared CubeH8.hdf5): detected, said on stderr, solved as the
// symmetric problem, and the reported error is the error on that problem.
#include <gtest/gtest.h>
#include <hdf5.h>

#include <Eigen/Dense>
#include <filesystem>
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

// M = [[2 1 0] [1 3 .5] [0 .5 4]] (symmetric positive definite), H = I, one 3D contact.
const double full_M[3][3] = {{2, 1, 0}, {1, 3, 0.5}, {0, 0.5, 4}};

/// Writes a global problem with M stored as `storage`: "upper", "lower", "full" or "skew"
/// (both triangles, not symmetric).
std::string write_global(const std::string& name, const std::string& storage) {
  const std::string path = (scratch_dir("fclib_triangle") / name).string();
  hid_t f = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  auto ints = [&](const char* p, std::vector<int> v) { h5_write(f, p, v); };
  auto dbls = [&](const char* p, std::vector<double> v) { h5_write(f, p, v); };
  hid_t lcpl = H5Pcreate(H5P_LINK_CREATE);
  H5Pset_create_intermediate_group(lcpl, 1);
  for (const char* g : {"/fclib_global/M", "/fclib_global/H", "/fclib_global/vectors"})
    H5Gclose(H5Gcreate2(f, g, lcpl, H5P_DEFAULT, H5P_DEFAULT));
  H5Pclose(lcpl);
  std::vector<int> i, p;
  std::vector<double> x;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) {
      double v = full_M[r][c];
      if (v == 0) continue;
      if (storage == "upper" && r > c) continue;
      if (storage == "lower" && r < c) continue;
      if (storage == "skew" && r > c) v *= 1.5;
      i.push_back(r);
      p.push_back(c);
      x.push_back(v);
    }
  ints("/fclib_global/spacedim", {3});
  ints("/fclib_global/M/m", {3});
  ints("/fclib_global/M/n", {3});
  ints("/fclib_global/M/nz", {static_cast<int>(x.size())});
  ints("/fclib_global/M/i", i);
  ints("/fclib_global/M/p", p);
  dbls("/fclib_global/M/x", x);
  ints("/fclib_global/H/m", {3});
  ints("/fclib_global/H/n", {3});
  ints("/fclib_global/H/nz", {3});
  ints("/fclib_global/H/i", {0, 1, 2});
  ints("/fclib_global/H/p", {0, 1, 2});
  dbls("/fclib_global/H/x", {1, 1, 1});
  dbls("/fclib_global/vectors/f", {-1, 0.4, 0.1});
  dbls("/fclib_global/vectors/w", {0, 0, 0});
  dbls("/fclib_global/vectors/mu", {0.3});
  H5Fclose(f);
  return path;
}

Eigen::Matrix3d symmetric_M() {
  Eigen::Matrix3d M;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) M(r, c) = full_M[r][c];
  return M;
}

}  // namespace

TEST(FclibTriangle, StorageIsRecognised) {
  using moreau::fclib::MatrixStorage;
  for (const char* s : {"upper", "lower", "full", "skew"}) {
    const auto path = write_global(std::string(s) + ".hdf5", s);
    if (std::string(s) == "skew") {
      try {
        moreau::fclib::read(path);
        ADD_FAILURE() << "an unsymmetric M was accepted";
      } catch (const moreau::InputError& e) {
        EXPECT_NE(e.describe().find("/fclib_global/M"), std::string::npos) << e.describe();
        EXPECT_NE(e.describe().find("not symmetric"), std::string::npos) << e.describe();
      }
      continue;
    }
    const auto p = moreau::fclib::read(path);
    // Whatever the storage, the problem is the one of the symmetric M.
    EXPECT_TRUE(Eigen::MatrixXd(p.global_problem.M).isApprox(Eigen::MatrixXd(symmetric_M()), 1e-15)) << s;
    const Eigen::Matrix3d W = symmetric_M().inverse();
    EXPECT_TRUE(Eigen::MatrixXd(p.local.W).isApprox(Eigen::MatrixXd(W), 1e-12)) << s;
    EXPECT_EQ(p.notes.size(), std::string(s) == "full" ? 0u : 1u) << s;
    if (!p.notes.empty()) EXPECT_NE(p.notes[0].find(std::string(s) + " triangle only"), std::string::npos) << p.notes[0];
  }
}

TEST(FclibTriangle, SolveSaysSoAndReportsTheErrorOfTheSymmetricProblem) {
  const auto path = write_global("upper_solve.hdf5", "upper");
  const fs::path dir = fs::path(path).parent_path();
  Result r = run_moreau({"fclib", "solve", path, "--solver", "nlgs", "--tol", "1e-12", "--solution", "sol.hdf5"}, dir);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("upper triangle only"), std::string::npos) << r.err;
  auto j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j["converged"].get<bool>()) << r.out;
  // The answer, checked on the symmetric problem built here independently of the reader.
  const auto sol = read_doubles((dir / "sol.hdf5").string(), "/solution/r");
  moreau::LocalProblem P;
  P.dim = 3;
  const Eigen::Matrix3d Minv = symmetric_M().inverse();
  P.W = Eigen::MatrixXd(Minv).sparseView();
  P.q = Minv * Eigen::Vector3d(-1, 0.4, 0.1);
  P.mu = Eigen::VectorXd::Constant(1, 0.3);
  const Eigen::VectorXd rr = Eigen::Map<const Eigen::VectorXd>(sol.data(), 3);
  EXPECT_LE(moreau::natural_map_error(P, rr), 1e-12);
  // Read literally, the triangle is another problem: the answer does not solve that one.
  moreau::LocalProblem D = P;
  const Eigen::Matrix3d Mdiag = Eigen::Vector3d(2, 3, 4).asDiagonal();
  D.W = Eigen::MatrixXd(Mdiag.inverse()).sparseView();
  D.q = Mdiag.inverse() * Eigen::Vector3d(-1, 0.4, 0.1);
  EXPECT_GT(moreau::natural_map_error(D, rr), 1e-3);
}
