// A whole FCLib local problem (DESIGN §3.5), laid out as FCLib's own writer does
// (fclib_write_local in fclib.c): int32 one-element m, n, nz, nzmax, spacedim; W in CSR
// (nz = -2, p the m+1 row pointers, i the column indices); info strings as fixed-length
// scalars. Siconos and FCLib's tools then read moreau's problems as they read the
// shared ones.
#include <Eigen/SparseCore>
#include <filesystem>
#include <moreau/error.hpp>
#include <vector>

#include "fclib.hpp"
#include "h5.hpp"

namespace moreau::fclib {

namespace {

namespace h5 = moreau::io::h5;

h5::Id make_group(hid_t where, const char* name) {
  h5::Id g = h5::group(H5Gcreate2(where, name, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
  if (!g) throw RunError(std::string("HDF5 write failed: group ") + name);
  return g;
}

void write_int(hid_t where, const std::string& name, long value) {
  const int v = static_cast<int>(value);
  h5::write_int32(where, name, &v, 1, 0);
}

/// A scalar fixed-length string, as H5LTmake_dataset_string (FCLib's choice) writes it.
void write_text(hid_t where, const std::string& name, const std::string& text) {
  h5::Id t = h5::type(H5Tcopy(H5T_C_S1));
  H5Tset_size(t.get(), text.size() + 1);  // with the terminating NUL, as strlen + 1
  h5::Id sp = h5::space(H5Screate(H5S_SCALAR));
  h5::Id ds = h5::dataset(H5Dcreate2(where, name.c_str(), t.get(), sp.get(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
  if (!ds || H5Dwrite(ds.get(), t.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, text.c_str()) < 0)
    throw RunError("HDF5 write failed: dataset " + name);
}

void write_vector(hid_t where, const std::string& name, const Eigen::VectorXd& v) {
  h5::write_doubles(where, name, v.data(), static_cast<hsize_t>(v.size()), 0);
}

void write_csr(hid_t where, const Eigen::SparseMatrix<double, Eigen::RowMajor>& W) {
  Eigen::SparseMatrix<double, Eigen::RowMajor> A = W;
  A.makeCompressed();
  const auto nnz = static_cast<hsize_t>(A.nonZeros());
  write_int(where, "m", A.rows());
  write_int(where, "n", A.cols());
  write_int(where, "nz", -2);
  write_int(where, "nzmax", static_cast<long>(nnz));
  h5::write_int32(where, "p", A.outerIndexPtr(), static_cast<hsize_t>(A.rows() + 1), 0);
  h5::write_int32(where, "i", A.innerIndexPtr(), nnz, 0);
  h5::write_doubles(where, "x", A.valuePtr(), nnz, 0);
}

void write_pair(hid_t where, const LocalProblem& p, const Eigen::VectorXd& r) {
  const Eigen::VectorXd u = p.W * r + p.q;
  write_vector(where, "r", r);
  write_vector(where, "u", u);
}

void write_file(const std::string& path, const LocalProblem& p, const ProblemInfo& info,
                const Eigen::VectorXd* guess_r, const Eigen::VectorXd* solution_r) {
  h5::MemoryFile f(path);
  if (!f) throw RunError("cannot create the FCLib problem file " + path + " in memory");
  h5::Id root = make_group(f.get(), "fclib_local");
  write_int(root.get(), "spacedim", p.dim);
  {
    h5::Id w = make_group(root.get(), "W");
    write_csr(w.get(), p.W);
  }
  {
    h5::Id v = make_group(root.get(), "vectors");
    write_vector(v.get(), "q", p.q);
    write_vector(v.get(), "mu", p.mu);
  }
  {
    h5::Id i = make_group(root.get(), "info");
    write_text(i.get(), "title", info.title);
    write_text(i.get(), "description", info.description);
    write_text(i.get(), "math_info", info.math_info);
  }
  if (guess_r) {
    h5::Id g = make_group(f.get(), "guesses");
    write_int(g.get(), "number_of_guesses", 1);
    h5::Id one = make_group(g.get(), "1");
    write_pair(one.get(), p, *guess_r);
  }
  if (solution_r) {
    h5::Id s = make_group(f.get(), "solution");
    write_pair(s.get(), p, *solution_r);
  }
  root.reset();
  // Written out through a temporary file renamed into place, errors named (h5.hpp).
  f.save_atomically(path);
}

}  // namespace

void write_local(const std::string& path, const LocalProblem& p, const ProblemInfo& info, const Eigen::VectorXd* guess_r,
                 const Eigen::VectorXd* solution_r) {
  const Eigen::Index n = p.dim * p.contacts();
  // Callers' faults, not the user's: a problem without its matrix or with sizes that disagree.
  if (p.W.rows() != n || p.W.cols() != n || p.q.size() != n)
    throw RunError("internal: FCLib export of a problem whose W (" + std::to_string(p.W.rows()) + "x" +
                   std::to_string(p.W.cols()) + ") or q (" + std::to_string(p.q.size()) + ") does not match " +
                   std::to_string(p.contacts()) + " contacts in dimension " + std::to_string(p.dim));
  for (const Eigen::VectorXd* r : {guess_r, solution_r})
    if (r && r->size() != n) throw RunError("internal: FCLib export of an impulse vector of the wrong size");
  write_file(path, p, info, guess_r, solution_r);
}

}  // namespace moreau::fclib
