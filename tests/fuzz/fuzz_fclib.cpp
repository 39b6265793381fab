// Fuzz target: an FCLib problem file read as `moreau fclib solve` reads it (fclib::read,
// which also reduces a global problem to the local one). The input is a list of HDF5
// objects (h5_records.hpp) written to a temporary file first.
//
// Every input must end as a problem a solver can take — every number finite, sizes
// consistent — or as an InputError naming the dataset. Anything else aborts.
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <moreau/error.hpp>
#include <string>

#include "h5_records.hpp"
#include "kernel/fclib/fclib.hpp"

namespace {

[[noreturn]] void finding(const char* what) {
  std::fprintf(stderr, "fuzz_fclib: %s\n", what);
  std::abort();
}

/// What read() promises to a solver.
void check_problem(const moreau::fclib::Problem& p) {
  const moreau::LocalProblem& P = p.local;
  const Eigen::Index n = P.dim * P.mu.size();
  if (P.dim != 2 && P.dim != 3) finding("dimension not 2 or 3");
  if (P.W.rows() != n || P.W.cols() != n || P.q.size() != n) finding("inconsistent sizes");
  if (!P.q.allFinite() || !P.mu.allFinite()) finding("non-finite q or mu");
  for (Eigen::Index k = 0; k < P.W.nonZeros(); ++k)
    if (!std::isfinite(P.W.valuePtr()[k])) finding("non-finite W");
  if (p.guess_r && (p.guess_r->size() != n || !p.guess_r->allFinite())) finding("bad guess");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::string path = moreau_fuzz::scratch_file("fclib.hdf5");
  if (!moreau_fuzz::write_records(data, size, path)) finding("cannot write the input file");
  try {
    check_problem(moreau::fclib::read(path));
  } catch (const moreau::InputError& e) {
    if (e.file() != path) finding("an input error that does not name the file");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fuzz_fclib: not an input error: %s\n", e.what());
    std::abort();
  } catch (...) {
    finding("an exception that is not a std::exception");
  }
  return 0;
}
