// Damaged FCLib files (issue 11: corrupted copies of the shared problems): non-finite
// numbers, NaN in a pointer array, absurd dimensions, huge declared datasets. Each is
// refused before any solver sees it, exit 2 naming the HDF5 dataset — never solved into a
// "converged" line, never exit 1, never a read out of bounds.
#include <gtest/gtest.h>
#include <hdf5.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <vector>

#include "cli_runner.hpp"
#include "h5_read.hpp"

namespace fs = std::filesystem;
using namespace moreau_test;

namespace {

const double kNaN = std::numeric_limits<double>::quiet_NaN();
const double kInf = std::numeric_limits<double>::infinity();

std::string shared(const std::string& name) { return std::string(MOREAU_SHARED_DIR) + "/fclib/" + name; }

/// A copy of a shared problem with dataset `path` replaced by `values` (as float64, the
/// way a file written by another code may store any array).
std::string damaged(const std::string& name, const std::string& file, const std::string& path,
                    const std::vector<double>& values) {
  const fs::path dir = scratch_dir("fclib_fault_" + name);
  const fs::path copy = dir / file;
  fs::copy_file(shared(file), copy);
  hid_t f = H5Fopen(copy.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  H5Ldelete(f, path.c_str(), H5P_DEFAULT);
  hsize_t n = values.size();
  hid_t s = H5Screate_simple(1, &n, nullptr);
  hid_t d = H5Dcreate2(f, path.c_str(), H5T_IEEE_F64LE, s, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  H5Dwrite(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data());
  H5Dclose(d);
  H5Sclose(s);
  H5Fclose(f);
  return copy.string();
}

/// The dataset of the shared file, as doubles, with entry `k` set to `x`.
std::vector<double> with(const std::string& file, const std::string& path, std::size_t k, double x) {
  std::vector<double> v = read_doubles(shared(file), path);
  v.at(k) = x;
  return v;
}

/// `moreau fclib solve` on `path`: exit 2, `where` named, and no JSON line on stdout.
void expect_refused(const std::string& path, const std::string& where, const std::string& what = "") {
  Result r = run_moreau({"fclib", "solve", path, "--solver", "nlgs", "--max-iter", "50"});
  EXPECT_EQ(r.code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find(path + ": at " + where + ": "), std::string::npos) << "expected " << where << " in:\n" << r.err;
  if (!what.empty()) EXPECT_NE(r.err.find(what), std::string::npos) << r.err;
  EXPECT_EQ(r.out.find("converged"), std::string::npos) << r.out;
}

const std::string kLocal = "fclib-local_problem_test.hdf5", kGlobal = "faf-Box_Stacks-i0035-31-0.hdf5";

}  // namespace

TEST(FclibFaults, NonFiniteVectorsAreRefusedNamingTheDataset) {
  expect_refused(damaged("q_nan", kLocal, "/fclib_local/vectors/q", with(kLocal, "/fclib_local/vectors/q", 5, kNaN)),
                 "/fclib_local/vectors/q", "entry 5 is nan");
  // An infinite q once gave "converged": true, "error": 0 (the error is divided by |q|).
  expect_refused(damaged("q_inf", kLocal, "/fclib_local/vectors/q", with(kLocal, "/fclib_local/vectors/q", 0, kInf)),
                 "/fclib_local/vectors/q", "entry 0 is inf");
  expect_refused(damaged("w_inf", kGlobal, "/fclib_global/vectors/w", with(kGlobal, "/fclib_global/vectors/w", 3, -kInf)),
                 "/fclib_global/vectors/w");
  expect_refused(damaged("f_nan", kGlobal, "/fclib_global/vectors/f", with(kGlobal, "/fclib_global/vectors/f", 7, kNaN)),
                 "/fclib_global/vectors/f");
  expect_refused(damaged("x_nan", kLocal, "/fclib_local/W/x", with(kLocal, "/fclib_local/W/x", 10, kNaN)), "/fclib_local/W/x");
  expect_refused(damaged("guess", kLocal, "/guesses/1/r", with(kLocal, "/guesses/1/r", 2, kNaN)), "/guesses/1/r");
}

TEST(FclibFaults, ANanInACsrPointerArrayIsRefusedNotReadOutOfBounds) {
  // NaN compares false with everything: it passed the "increasing" check and the reader
  // then walked the heap past i and x (AddressSanitizer).
  expect_refused(damaged("p_nan", kLocal, "/fclib_local/W/p", with(kLocal, "/fclib_local/W/p", 7, kNaN)), "/fclib_local/W/p",
                 "pointer 7 = nan is not an integer");
  expect_refused(damaged("p_last", kLocal, "/fclib_local/W/p", with(kLocal, "/fclib_local/W/p", 144, 1e9)),
                 "/fclib_local/W/p");
  expect_refused(damaged("p_frac", kLocal, "/fclib_local/W/p", with(kLocal, "/fclib_local/W/p", 3, 100.5)),
                 "/fclib_local/W/p");
}

TEST(FclibFaults, AbsurdDimensionsAreRefusedBeforeAnyAllocation) {
  // m, n near 2^31 ended in bad_alloc (exit 1).
  expect_refused(damaged("m_big", kLocal, "/fclib_local/W/m", {2147483647.0}), "/fclib_local/W", "the matrix is 2147483647x144");
  expect_refused(damaged("n_big", kGlobal, "/fclib_global/H/n", {2147483000.0}), "/fclib_global/H");
  expect_refused(damaged("m_nan", kGlobal, "/fclib_global/M/m", {kNaN}), "/fclib_global/M/m", "expected an integer");
  expect_refused(damaged("dim", kLocal, "/fclib_local/spacedim", {1e300}), "/fclib_local/spacedim");
  expect_refused(damaged("nz", kGlobal, "/fclib_global/M/nz", {-7}), "/fclib_global/M/nz");
}

TEST(FclibFaults, AHugeDeclaredDatasetIsRefusedByItsSize) {
  // 2^40 values declared in a few bytes (chunked, nothing written): reading them would ask
  // the OS for 8 TB.
  const fs::path dir = scratch_dir("fclib_fault_huge");
  const fs::path copy = dir / kLocal;
  fs::copy_file(shared(kLocal), copy);
  hid_t f = H5Fopen(copy.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  H5Ldelete(f, "/fclib_local/vectors/mu", H5P_DEFAULT);
  hsize_t n = hsize_t{1} << 40, chunk = 1024;
  hid_t s = H5Screate_simple(1, &n, nullptr);
  hid_t dcpl = H5Pcreate(H5P_DATASET_CREATE);
  H5Pset_chunk(dcpl, 1, &chunk);
  hid_t d = H5Dcreate2(f, "/fclib_local/vectors/mu", H5T_IEEE_F64LE, s, H5P_DEFAULT, dcpl, H5P_DEFAULT);
  H5Dclose(d);
  H5Pclose(dcpl);
  H5Sclose(s);
  H5Fclose(f);
  expect_refused(copy.string(), "/fclib_local/vectors/mu", "declares 1099511627776 values");
}
