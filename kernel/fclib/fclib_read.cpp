#include <algorithm>
#include <cmath>
#include <limits>
#include <moreau/error.hpp>

#include "fclib.hpp"
#include "h5.hpp"

namespace moreau::fclib {

namespace {

namespace h5 = moreau::io::h5;

std::vector<double> vec(hid_t f, const std::string& path, const std::string& file) {
  return h5::read_doubles(f, path, nullptr, file);
}

/// Every value finite: a NaN or an infinity in a problem makes every error measure and
/// every comparison meaningless (an infinite q gave "converged" with error 0).
void require_finite(const std::vector<double>& v, const std::string& path, const std::string& file) {
  for (std::size_t k = 0; k < v.size(); ++k)
    if (!std::isfinite(v[k]))
      throw InputError(path, "entry " + std::to_string(k) + " is " + std::to_string(v[k]) + ": expected a finite number",
                       file);
}

/// An integer stored as a number (FCLib writes them as int or double datasets).
bool is_integer(double v, double lo, double hi) { return std::isfinite(v) && v == std::floor(v) && v >= lo && v <= hi; }

long scalar(hid_t f, const std::string& path, const std::string& file) {
  auto v = vec(f, path, file);
  if (v.size() != 1) throw InputError(path, "expected one integer, found " + std::to_string(v.size()) + " values", file);
  if (!is_integer(v[0], -2147483648.0, 2147483647.0))
    throw InputError(path, "expected an integer, found " + std::to_string(v[0]), file);
  return static_cast<long>(v[0]);
}

/// A matrix group: m, n, nz (−2 CSR, −1 CSC, ≥ 0 triplet with i rows and p columns), p, i,
/// x. `rows` × `cols` is what the problem needs, checked before anything is allocated (an
/// absurd m or n must not become a huge allocation).
Eigen::SparseMatrix<double> matrix(hid_t f, const std::string& g, const std::string& file, Eigen::Index rows,
                                   Eigen::Index cols) {
  const long m = scalar(f, g + "/m", file), n = scalar(f, g + "/n", file), nz = scalar(f, g + "/nz", file);
  if (m < 0 || n < 0) throw InputError(g, "negative matrix dimensions", file);
  if (m != rows || n != cols)
    throw InputError(g, "the matrix is " + std::to_string(m) + "x" + std::to_string(n) + ", expected " +
                            std::to_string(rows) + "x" + std::to_string(cols) + " (from the problem's vectors)", file);
  const auto p = vec(f, g + "/p", file), i = vec(f, g + "/i", file), x = vec(f, g + "/x", file);
  std::vector<Eigen::Triplet<double>> t;
  auto check_index = [&](double v, long limit, const char* what, std::size_t k) {
    if (!is_integer(v, 0, static_cast<double>(limit) - 1))
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
    // Every pointer an integer in [0, entries], non-decreasing (a NaN fails every
    // comparison, so it is refused by name rather than by an order test).
    const double entries = static_cast<double>(std::min(i.size(), x.size()));
    for (long o = 0; o <= outer; ++o) {
      if (!is_integer(p[o], 0, entries))
        throw InputError(g + "/p", "pointer " + std::to_string(o) + " = " + std::to_string(p[o]) +
                                       " is not an integer between 0 and the " + std::to_string(static_cast<long>(entries)) +
                                       " entries of i and x", file);
      if (o > 0 && p[o] < p[o - 1])
        throw InputError(g + "/p", "pointers are not increasing at " + std::to_string(o - 1), file);
    }
    for (long o = 0; o < outer; ++o) {
      for (long k = static_cast<long>(p[o]); k < static_cast<long>(p[o + 1]); ++k) {
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

/// A vector dataset, every entry finite.
Eigen::VectorXd finite_vector(hid_t f, const std::string& path, const std::string& file) {
  const std::vector<double> v = vec(f, path, file);
  require_finite(v, path, file);
  return eigen(v);
}

void check_mu(const Eigen::VectorXd& mu, const std::string& path, const std::string& file) {
  for (Eigen::Index k = 0; k < mu.size(); ++k)
    if (!(mu[k] >= 0) || !std::isfinite(mu[k]))
      throw InputError(path, "friction coefficient " + std::to_string(k) + " is " + std::to_string(mu[k]) +
                                 ": expected a finite value >= 0", file);
}

/// A vector of `n` values (the problem's size).
void check_size(const Eigen::VectorXd& v, Eigen::Index n, const std::string& path, const std::string& file) {
  if (v.size() != n)
    throw InputError(path, "expected " + std::to_string(n) + " values, found " + std::to_string(v.size()), file);
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
  if (n > std::numeric_limits<int>::max())  // Eigen's sparse indices are int
    throw InputError(root + "/vectors/mu", std::to_string(nc) + " contacts: too many for one problem", path);
  if (local) {
    p.local.dim = static_cast<int>(dim);
    p.local.q = finite_vector(f.get(), "/fclib_local/vectors/q", path);
    check_size(p.local.q, n, "/fclib_local/vectors/q", path);
    p.local.W = matrix(f.get(), "/fclib_local/W", path, n, n);
    p.local.mu = mu;
  } else {
    p.global = true;
    GlobalProblem& g = p.global_problem;
    g.dim = static_cast<int>(dim);
    g.f = finite_vector(f.get(), "/fclib_global/vectors/f", path);
    g.w = finite_vector(f.get(), "/fclib_global/vectors/w", path);
    check_size(g.w, n, "/fclib_global/vectors/w", path);
    const Eigen::Index ndof = g.f.size();  // M is ndof × ndof and H ndof × n
    g.M = matrix(f.get(), "/fclib_global/M", path, ndof, ndof);
    {  // a symmetric M may be stored as one triangle
      std::string note;
      g.M = symmetric_matrix(g.M, "/fclib_global/M", path, &note);
      if (!note.empty()) p.notes.push_back(note);
    }
    g.H = matrix(f.get(), "/fclib_global/H", path, ndof, n);
    g.mu = mu;
    p.local = reduce(g, path);
    // A nearly singular M (a diagonal entry of 1e-320) reduces to infinite W or q.
    const bool finite_W = std::all_of(p.local.W.valuePtr(), p.local.W.valuePtr() + p.local.W.nonZeros(),
                                      [](double v) { return std::isfinite(v); });
    if (!finite_W || !p.local.q.allFinite())
      throw InputError("/fclib_global/M", "the reduced problem (W = Ht M^-1 H, q = w + Ht M^-1 f) is not finite: "
                                          "M is singular or nearly so", path);
  }
  if (h5::exists(f.get(), "/guesses/1/r")) {
    // A guess of another size is kept out (`fclib solve --warm-start` says so); a non-finite one is refused.
    Eigen::VectorXd r = finite_vector(f.get(), "/guesses/1/r", path);
    if (r.size() == n) p.guess_r = r;
  }
  return p;
}

}  // namespace moreau::fclib
