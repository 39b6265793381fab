#include <cmath>
#include <moreau/error.hpp>

#include "fclib.hpp"
#include "h5.hpp"

namespace moreau::fclib {

namespace {

namespace h5 = moreau::io::h5;

std::vector<double> vec(hid_t f, const std::string& path, const std::string& file) {
  return h5::read_doubles(f, path, nullptr, file);
}

long scalar(hid_t f, const std::string& path, const std::string& file) {
  auto v = vec(f, path, file);
  if (v.size() != 1) throw InputError(path, "expected one integer, found " + std::to_string(v.size()) + " values", file);
  return std::lround(v[0]);
}

/// A matrix group: m, n, nz (−2 CSR, −1 CSC, ≥ 0 triplet with i rows and p columns), p, i, x.
Eigen::SparseMatrix<double> matrix(hid_t f, const std::string& g, const std::string& file) {
  const long m = scalar(f, g + "/m", file), n = scalar(f, g + "/n", file), nz = scalar(f, g + "/nz", file);
  if (m < 0 || n < 0) throw InputError(g, "negative matrix dimensions", file);
  const auto p = vec(f, g + "/p", file), i = vec(f, g + "/i", file), x = vec(f, g + "/x", file);
  std::vector<Eigen::Triplet<double>> t;
  auto check_index = [&](double v, long limit, const char* what, std::size_t k) {
    if (!(v >= 0 && v < limit) || v != std::floor(v))
      throw InputError(g + "/" + what, "entry " + std::to_string(k) + " = " + std::to_string(v) + " is not an index below " +
                                         std::to_string(limit), file);
    return static_cast<long>(v);
  };
  if (nz >= 0) {
    if (i.size() < static_cast<std::size_t>(nz) || p.size() < static_cast<std::size_t>(nz) || x.size() < static_cast<std::size_t>(nz))
      throw InputError(g + "/nz", "nz = " + std::to_string(nz) + " but i, p, x hold " + std::to_string(i.size()) + ", " +
                                      std::to_string(p.size()) + ", " + std::to_string(x.size()) + " entries", file);
    for (long k = 0; k < nz; ++k)
      t.emplace_back(check_index(i[k], m, "i", k), check_index(p[k], n, "p", k), x[k]);
  } else if (nz == -1 || nz == -2) {
    const long outer = nz == -2 ? m : n, inner = nz == -2 ? n : m;
    if (static_cast<long>(p.size()) != outer + 1)
      throw InputError(g + "/p", "expected " + std::to_string(outer + 1) + " pointers for a " +
                                     (nz == -2 ? "CSR" : "CSC") + " matrix, found " + std::to_string(p.size()), file);
    const long nnz = std::lround(p[outer]);
    if (nnz < 0 || static_cast<long>(i.size()) < nnz || static_cast<long>(x.size()) < nnz)
      throw InputError(g + "/i", "the pointers announce " + std::to_string(nnz) + " entries, i and x hold " +
                                     std::to_string(i.size()) + " and " + std::to_string(x.size()), file);
    for (long o = 0; o < outer; ++o) {
      if (p[o] > p[o + 1] || p[o] < 0) throw InputError(g + "/p", "pointers are not increasing at " + std::to_string(o), file);
      for (long k = std::lround(p[o]); k < std::lround(p[o + 1]); ++k) {
        const long in = check_index(i[k], inner, "i", k);
        if (nz == -2) t.emplace_back(o, in, x[k]);
        else t.emplace_back(in, o, x[k]);
      }
    }
  } else {
    throw InputError(g + "/nz", "unknown matrix layout nz = " + std::to_string(nz) + " (expected -2, -1 or >= 0)", file);
  }
  for (const auto& e : t)
    if (!std::isfinite(e.value())) throw InputError(g + "/x", "non-finite matrix entry", file);
  Eigen::SparseMatrix<double> A(m, n);
  A.setFromTriplets(t.begin(), t.end());
  return A;
}

Eigen::VectorXd eigen(const std::vector<double>& v) {
  return Eigen::Map<const Eigen::VectorXd>(v.data(), static_cast<Eigen::Index>(v.size()));
}

void check_mu(const Eigen::VectorXd& mu, const std::string& path, const std::string& file) {
  for (Eigen::Index k = 0; k < mu.size(); ++k)
    if (!(mu[k] >= 0) || !std::isfinite(mu[k]))
      throw InputError(path, "friction coefficient " + std::to_string(k) + " is " + std::to_string(mu[k]) +
                                 ": expected a finite value >= 0", file);
}

}  // namespace

Problem read(const std::string& path) {
  h5::quiet();
  h5::Id f = h5::file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT));
  if (!f) throw InputError("", "cannot open as an HDF5 file (missing, unreadable or truncated)", path);
  Problem p;
  const bool local = h5::exists(f.get(), "/fclib_local"), global = h5::exists(f.get(), "/fclib_global");
  if (!local && !global) throw InputError("/", "neither /fclib_local nor /fclib_global: not an FCLib problem", path);
  const std::string root = local ? "/fclib_local" : "/fclib_global";
  const long dim = scalar(f.get(), root + "/spacedim", path);
  if (dim != 2 && dim != 3) throw InputError(root + "/spacedim", "expected 2 or 3, found " + std::to_string(dim), path);
  const Eigen::VectorXd mu = eigen(vec(f.get(), root + "/vectors/mu", path));
  check_mu(mu, root + "/vectors/mu", path);
  const Eigen::Index nc = mu.size(), n = dim * nc;
  if (local) {
    p.local.dim = static_cast<int>(dim);
    p.local.W = matrix(f.get(), "/fclib_local/W", path);
    p.local.q = eigen(vec(f.get(), "/fclib_local/vectors/q", path));
    p.local.mu = mu;
    if (p.local.W.rows() != n || p.local.W.cols() != n)
      throw InputError("/fclib_local/W", "W is " + std::to_string(p.local.W.rows()) + "x" + std::to_string(p.local.W.cols()) +
                                             ", expected " + std::to_string(n) + "x" + std::to_string(n) + " (spacedim x contacts)", path);
    if (p.local.q.size() != n)
      throw InputError("/fclib_local/vectors/q", "expected " + std::to_string(n) + " values, found " + std::to_string(p.local.q.size()), path);
  } else {
    p.global = true;
    GlobalProblem& g = p.global_problem;
    g.dim = static_cast<int>(dim);
    g.M = matrix(f.get(), "/fclib_global/M", path);
    if (g.M.rows() == g.M.cols()) {  // a symmetric M may be stored as one triangle
      std::string note;
      g.M = symmetric_matrix(g.M, "/fclib_global/M", path, &note);
      if (!note.empty()) p.notes.push_back(note);
    }
    g.H = matrix(f.get(), "/fclib_global/H", path);
    g.f = eigen(vec(f.get(), "/fclib_global/vectors/f", path));
    g.w = eigen(vec(f.get(), "/fclib_global/vectors/w", path));
    g.mu = mu;
    const Eigen::Index ndof = g.M.rows();
    if (g.M.cols() != ndof) throw InputError("/fclib_global/M", "M is not square", path);
    if (g.H.rows() != ndof || g.H.cols() != n)
      throw InputError("/fclib_global/H", "H is " + std::to_string(g.H.rows()) + "x" + std::to_string(g.H.cols()) +
                                              ", expected " + std::to_string(ndof) + "x" + std::to_string(n), path);
    if (g.f.size() != ndof) throw InputError("/fclib_global/vectors/f", "expected " + std::to_string(ndof) + " values", path);
    if (g.w.size() != n) throw InputError("/fclib_global/vectors/w", "expected " + std::to_string(n) + " values", path);
    p.local = reduce(g, path);
  }
  if (h5::exists(f.get(), "/guesses/1/r")) {
    Eigen::VectorXd r = eigen(vec(f.get(), "/guesses/1/r", path));
    if (r.size() == n) p.guess_r = r;
  }
  return p;
}

}  // namespace moreau::fclib
