// Whole FCLib problems, local and global (DESIGN §3.5), laid out as FCLib's own writer does
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

void write_csr(hid_t where, const Eigen::SparseMatrix<double, Eigen::RowMajor>& W) {  // any matrix, as CSR
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

/// The "info" group both forms carry.
void write_info(hid_t root, const ProblemInfo& info) {
  h5::Id i = make_group(root, "info");
  write_text(i.get(), "title", info.title);
  write_text(i.get(), "description", info.description);
  write_text(i.get(), "math_info", info.math_info);
}

/// /guesses/1 and /solution, each written by `write_one(group, r)` (the local form's (r, u),
/// the global form's (r, v, u)).
template <class WriteOne>
void write_guess_and_solution(hid_t file, const Eigen::VectorXd* guess_r, const Eigen::VectorXd* solution_r,
                              const WriteOne& write_one) {
  if (guess_r) {
    h5::Id g = make_group(file, "guesses");
    write_int(g.get(), "number_of_guesses", 1);
    h5::Id one = make_group(g.get(), "1");
    write_one(one.get(), *guess_r);
  }
  if (solution_r) {
    h5::Id s = make_group(file, "solution");
    write_one(s.get(), *solution_r);
  }
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
  write_info(root.get(), info);
  write_guess_and_solution(f.get(), guess_r, solution_r,
                           [&](hid_t where, const Eigen::VectorXd& r) { write_pair(where, p, r); });
  root.reset();
  // Written out through a temporary file renamed into place, errors named (h5.hpp).
  f.save_atomically(path);
}

/// FCLib's global form (fclib_write_global): M, H as CSR, vectors f, w, mu; guesses and
/// solution as (r, v, u) with v = M⁻¹(H r + f), u = Hᵀ v + w.
void write_global_file(const std::string& path, const GlobalProblem& g, const ProblemInfo& info,
                       const Eigen::VectorXd* guess_r, const Eigen::VectorXd* solution_r) {
  h5::MemoryFile f(path);
  if (!f) throw RunError("cannot create the FCLib problem file " + path + " in memory");
  h5::Id root = make_group(f.get(), "fclib_global");
  write_int(root.get(), "spacedim", g.dim);
  for (const auto& [name, A] : {std::pair<const char*, const Eigen::SparseMatrix<double>*>{"M", &g.M}, {"H", &g.H}}) {
    h5::Id m = make_group(root.get(), name);
    write_csr(m.get(), Eigen::SparseMatrix<double, Eigen::RowMajor>(*A));
  }
  {
    h5::Id v = make_group(root.get(), "vectors");
    write_vector(v.get(), "f", g.f);
    write_vector(v.get(), "w", g.w);
    write_vector(v.get(), "mu", g.mu);
  }
  write_info(root.get(), info);
  auto triple = [&](hid_t where, const Eigen::VectorXd& r) {
    const Eigen::VectorXd v = global_velocity(g, r);
    write_vector(where, "r", r);
    write_vector(where, "v", v);
    write_vector(where, "u", Eigen::VectorXd(g.H.transpose() * v + g.w));
  };
  write_guess_and_solution(f.get(), guess_r, solution_r, triple);
  root.reset();
  f.save_atomically(path);  // as write_file
}

}  // namespace

void write_global(const std::string& path, const GlobalProblem& g, const ProblemInfo& info, const Eigen::VectorXd* guess_r,
                  const Eigen::VectorXd* solution_r) {
  const Eigen::Index n = g.dim * g.mu.size(), ndof = g.M.rows();
  if (g.M.cols() != ndof || g.H.rows() != ndof || g.H.cols() != n || g.f.size() != ndof || g.w.size() != n)
    throw RunError("internal: FCLib export of a global problem whose sizes disagree");
  for (const Eigen::VectorXd* r : {guess_r, solution_r})
    if (r && r->size() != n) throw RunError("internal: FCLib export of an impulse vector of the wrong size");
  write_global_file(path, g, info, guess_r, solution_r);
}

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
