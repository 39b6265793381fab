#include "sparse_cholesky.hpp"

#include <Eigen/SparseCholesky>
#include <cmath>
#include <stdexcept>
#include <string>

#ifdef MOREAU_FEM_CHOLMOD
#include <Eigen/CholmodSupport>
#endif

namespace moreau::fem {
namespace {

using Sparse = Eigen::SparseMatrix<double>;

/// A simplicial factor P A Pᵀ = L D Lᵀ as compressed columns: column j holds its entries
/// at colptr[j] … colptr[j] + count[j] − 1 (rows below j, and the diagonal where it is
/// stored), `pivot[i]` the pivot of row i of A. LLᵀ: the diagonal L_jj stored in its
/// column, D = 1 (`diagonal` null). LDLᵀ: L's diagonal is 1, D in `diagonal` (CHOLMOD keeps
/// D where the diagonal would be: `diagonal_in_column`).
struct FactorView {
  Eigen::Index n = 0;
  const int* colptr = nullptr;
  const int* count = nullptr;  ///< null: colptr[j + 1] − colptr[j]
  const int* row = nullptr;
  const double* value = nullptr;
  bool ll = false;
  bool diagonal_in_column = false;  ///< the first entry of each column is the diagonal (L_jj or D_j)
  const double* diagonal = nullptr;  ///< LDLᵀ with D apart (Eigen)
  std::vector<double> own_diagonal;  ///< where `diagonal` points when the backend gives D by value
  std::vector<int> pivot;
};

struct Solver {
  virtual ~Solver() = default;
  virtual void analyze(const Sparse& A) = 0;
  virtual void factor(const Sparse& A) = 0;
  virtual Eigen::ComputationInfo info() const = 0;
  /// An LDLᵀ succeeds on indefinite matrices; the caller needs positive definite ones.
  virtual bool positive_pivots() const { return true; }
  virtual Eigen::VectorXd solve(const Eigen::VectorXd& b) const = 0;
  virtual Eigen::MatrixXd solve(const Eigen::MatrixXd& B) const = 0;
  /// The factor as compressed columns, for factor_column; false when it has none to show.
  virtual bool factor_view(FactorView&) const { return false; }
};

template <class S>
struct SolverOf final : Solver {
  S s;
  SolverOf() {
    // CHOLMOD prints its own warnings on stderr; the caller gets an exception instead.
    if constexpr (requires { s.cholmod().print; }) s.cholmod().print = 0;
  }
  void analyze(const Sparse& A) override { s.analyzePattern(A); }
  void factor(const Sparse& A) override { s.factorize(A); }
  Eigen::ComputationInfo info() const override { return s.info(); }
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const override { return s.solve(b); }
  Eigen::MatrixXd solve(const Eigen::MatrixXd& B) const override { return s.solve(B); }
  bool positive_pivots() const override {
    if constexpr (requires { s.vectorD(); }) return s.vectorD().size() == 0 || s.vectorD().minCoeff() > 0;
    else if constexpr (requires { s.positive_pivots(); }) return s.positive_pivots();
    else return true;
  }
  bool factor_view(FactorView& v) const override {
    if constexpr (requires { s.view(v); }) return s.view(v);
    else if constexpr (requires { s.vectorD(); }) {
      // Eigen's LDLᵀ: L strictly lower (rows ascending), D apart, P A P⁻¹ = L D Lᵀ.
      const auto& L = s.matrixL().nestedExpression();
      v.n = L.rows();
      v.colptr = L.outerIndexPtr();
      v.count = L.innerNonZeroPtr();
      v.row = L.innerIndexPtr();
      v.value = L.valuePtr();
      v.ll = false;
      v.diagonal_in_column = false;
      const Eigen::VectorXd D = s.vectorD();  // returned by value: kept in the view
      v.own_diagonal.assign(D.data(), D.data() + D.size());
      v.diagonal = v.own_diagonal.data();
      const auto& p = s.permutationP().indices();
      v.pivot.assign(p.data(), p.data() + p.size());
      return true;
    } else
      return false;
  }
};

#ifdef MOREAU_FEM_CHOLMOD
/// CHOLMOD's simplicial factor (int indices, as Eigen's wrapper makes it).
bool cholmod_view(const cholmod_factor* L, FactorView& v) {
  if (!L || L->is_super || L->xtype != CHOLMOD_REAL || L->itype != CHOLMOD_INT || !L->x) return false;
  v.n = static_cast<Eigen::Index>(L->n);
  v.colptr = static_cast<const int*>(L->p);
  v.count = static_cast<const int*>(L->nz);
  v.row = static_cast<const int*>(L->i);
  v.value = static_cast<const double*>(L->x);
  v.ll = L->is_ll;
  v.diagonal_in_column = true;
  v.diagonal = nullptr;
  // Perm[k] = the row of A at pivot k.
  const int* perm = static_cast<const int*>(L->Perm);
  v.pivot.assign(L->n, 0);
  for (std::size_t k = 0; k < L->n; ++k) v.pivot[static_cast<std::size_t>(perm ? perm[k] : static_cast<int>(k))] = static_cast<int>(k);
  return true;
}
#endif

#ifdef MOREAU_FEM_CHOLMOD
/// CHOLMOD's simplicial LDLᵀ with a look at D (the first entry of each column of its factor).
struct CholmodLdlt : Eigen::CholmodSimplicialLDLT<Sparse, Eigen::Lower> {
  bool positive_pivots() const {
    const cholmod_factor* L = this->m_cholmodFactor;
    if (!L || L->is_ll || L->is_super || L->xtype == CHOLMOD_PATTERN || !L->x) return true;
    const int* p = static_cast<const int*>(L->p);
    const double* x = static_cast<const double*>(L->x);
    for (std::size_t j = 0; j < L->n; ++j)
      if (!(x[p[j]] > 0)) return false;
    return true;
  }
  bool view(FactorView& v) const { return cholmod_view(this->m_cholmodFactor, v); }
};

/// CHOLMOD's supernodal LLᵀ (dense blocks through BLAS: the fastest factorisation in 3D),
/// its factor then converted to simplicial form (cholmod_change_factor, in place, a few %
/// of the factorisation's time), whose solves — one column at a time, as a run does them —
/// are the simplicial ones, 1.4–2× faster than the supernodal ones with a reference BLAS.
struct CholmodSupernodal : Eigen::CholmodSupernodalLLT<Sparse, Eigen::Lower> {
  void factorize(const Sparse& A) {
    Eigen::CholmodSupernodalLLT<Sparse, Eigen::Lower>::factorize(A);
    if (this->info() != Eigen::Success || !this->m_cholmodFactor) return;
    if (!cholmod_change_factor(CHOLMOD_REAL, 1, 0, 1, 1, this->m_cholmodFactor, &this->cholmod()))
      this->m_info = Eigen::NumericalIssue;
  }
  bool view(FactorView& v) const { return cholmod_view(this->m_cholmodFactor, v); }
};

/// The supernodal one above, which a numeric refactorisation cannot reuse once its factor
/// is simplicial: it analyses again.
template <>
struct SolverOf<CholmodSupernodal> final : Solver {
  std::unique_ptr<CholmodSupernodal> s = std::make_unique<CholmodSupernodal>();
  bool factored = false;
  SolverOf() { s->cholmod().print = 0; }
  void analyze(const Sparse& A) override {
    if (factored) {
      s = std::make_unique<CholmodSupernodal>();
      s->cholmod().print = 0;
      factored = false;
    }
    s->analyzePattern(A);
  }
  void factor(const Sparse& A) override {
    if (factored) analyze(A);
    s->factorize(A);
    factored = true;
  }
  Eigen::ComputationInfo info() const override { return s->info(); }
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const override { return s->solve(b); }
  Eigen::MatrixXd solve(const Eigen::MatrixXd& B) const override { return s->solve(B); }
  bool factor_view(FactorView& v) const override { return s->view(v); }
};
#endif

/// A body whose every DOF is fixed has a 0 × 0 matrix: nothing to factorise or solve
/// (CHOLMOD's analysis of an empty matrix gives no factor, which Eigen's wrapper then reads).
struct EmptySolver final : Solver {
  void analyze(const Sparse&) override {}
  void factor(const Sparse&) override {}
  Eigen::ComputationInfo info() const override { return Eigen::Success; }
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const override { return b; }
  Eigen::MatrixXd solve(const Eigen::MatrixXd& B) const override { return B; }
};

std::unique_ptr<Solver> make_solver(CholeskyBackend backend) {
  switch (backend) {
    case CholeskyBackend::eigen_ldlt:
      return std::make_unique<SolverOf<Eigen::SimplicialLDLT<Sparse, Eigen::Lower, Eigen::AMDOrdering<int>>>>();
    case CholeskyBackend::eigen_llt:
      return std::make_unique<SolverOf<Eigen::SimplicialLLT<Sparse, Eigen::Lower, Eigen::AMDOrdering<int>>>>();
#ifdef MOREAU_FEM_CHOLMOD
    case CholeskyBackend::cholmod_supernodal:
      return std::make_unique<SolverOf<CholmodSupernodal>>();
    case CholeskyBackend::cholmod_simplicial:
      return std::make_unique<SolverOf<CholmodLdlt>>();
#else
    case CholeskyBackend::cholmod_supernodal:
    case CholeskyBackend::cholmod_simplicial:
#endif
    case CholeskyBackend::automatic:
      break;
  }
  throw std::runtime_error("sparse Cholesky backend '" + std::string(backend_name(backend)) +
                           "' is not available in this build (CHOLMOD needs SuiteSparse: libsuitesparse-dev)");
}

}  // namespace

std::string_view backend_name(CholeskyBackend backend) {
  switch (backend) {
    case CholeskyBackend::automatic: return "automatic";
    case CholeskyBackend::eigen_ldlt: return "eigen-ldlt";
    case CholeskyBackend::eigen_llt: return "eigen-llt";
    case CholeskyBackend::cholmod_supernodal: return "cholmod-supernodal";
    case CholeskyBackend::cholmod_simplicial: return "cholmod-simplicial";
  }
  return "?";
}

CholeskyBackend backend_from_name(std::string_view name) {
  std::string valid;
  for (CholeskyBackend b : {CholeskyBackend::automatic, CholeskyBackend::eigen_ldlt, CholeskyBackend::eigen_llt,
                            CholeskyBackend::cholmod_supernodal, CholeskyBackend::cholmod_simplicial}) {
    if (backend_name(b) == name) return b;
    valid += (valid.empty() ? "" : ", ") + std::string(backend_name(b));
  }
  throw std::invalid_argument("unknown sparse Cholesky backend '" + std::string(name) + "'; valid: " + valid);
}

bool backend_available(CholeskyBackend backend) {
#ifdef MOREAU_FEM_CHOLMOD
  (void)backend;
  return true;
#else
  return backend != CholeskyBackend::cholmod_supernodal && backend != CholeskyBackend::cholmod_simplicial;
#endif
}

CholeskyBackend automatic_backend() {
  // The benchmark (docs/deformable.md, tests/fem/bench_cholesky.cpp) with Debian's
  // reference BLAS: CHOLMOD's supernodal LLᵀ factorises fastest (1.7–3.6× its simplicial
  // LDLᵀ in 3D, alike in 2D), and once its factor is converted to simplicial form it
  // solves as fast as the simplicial one (2–4× Eigen's). A run factorises once and solves
  // every step (free velocity, then LHS⁻¹ H for W): both count.
  // Without CHOLMOD, Eigen's LDLᵀ (as fast as its LLᵀ, never slower to factorise).
  return backend_available(CholeskyBackend::cholmod_supernodal) ? CholeskyBackend::cholmod_supernodal
                                                                  : CholeskyBackend::eigen_ldlt;
}

struct SparseCholesky::Impl {
  CholeskyBackend requested, resolved = CholeskyBackend::automatic;
  Eigen::Index rows = 0;
  std::unique_ptr<Solver> solver;
  // factor_column: the factor's view, its elimination tree (parent of each pivot: the
  // first row below the diagonal in its column, −1 at a root), a zeroed scratch vector.
  bool viewed = false, has_view = false;
  FactorView view;
  std::vector<int> parent;
  mutable std::vector<double> scratch;

  void reset_view() {
    viewed = has_view = false;
    view = FactorView{};
    parent.clear();
    scratch.clear();
  }
  void make_view() {
    viewed = true;
    has_view = solver && solver->factor_view(view);
    if (!has_view) return;
    parent.assign(static_cast<std::size_t>(view.n), -1);
    for (Eigen::Index j = 0; j < view.n; ++j) {
      const int begin = view.colptr[j] + (view.diagonal_in_column ? 1 : 0);
      const int end = view.colptr[j] + (view.count ? view.count[j] : view.colptr[j + 1] - view.colptr[j]);
      int first = -1;
      for (int q = begin; q < end; ++q)
        if (first < 0 || view.row[q] < first) first = view.row[q];
      parent[static_cast<std::size_t>(j)] = first;
    }
    scratch.assign(static_cast<std::size_t>(view.n), 0.0);
  }

  void check(const char* step, bool factored) const {
    Eigen::ComputationInfo info = solver->info();
    if (factored && info == Eigen::Success && !solver->positive_pivots()) info = Eigen::NumericalIssue;
    if (info == Eigen::Success) return;
    throw std::runtime_error(std::string("sparse Cholesky (") + std::string(backend_name(resolved)) + ") " + step +
                             " failed: " +
                             (info == Eigen::NumericalIssue
                                  ? "the matrix is not positive definite (a body free to move as a rigid body with "
                                    "no mass, or a non-positive mass or stiffness)"
                                  : "out of memory or invalid input"));
  }
};

SparseCholesky::SparseCholesky(CholeskyBackend backend) : impl_(std::make_unique<Impl>()) {
  impl_->requested = backend;
  if (backend != CholeskyBackend::automatic && !backend_available(backend)) make_solver(backend);  // throws
}

SparseCholesky::~SparseCholesky() = default;
SparseCholesky::SparseCholesky(SparseCholesky&&) noexcept = default;
SparseCholesky& SparseCholesky::operator=(SparseCholesky&&) noexcept = default;

void SparseCholesky::factorize(const Eigen::SparseMatrix<double>& A) {
  if (A.rows() != A.cols()) throw std::invalid_argument("sparse Cholesky: the matrix is not square");
  Impl& m = *impl_;
  m.resolved = m.requested == CholeskyBackend::automatic ? automatic_backend() : m.requested;
  m.solver = A.rows() == 0 ? std::make_unique<EmptySolver>() : make_solver(m.resolved);
  m.reset_view();
  m.rows = A.rows();
  m.solver->analyze(A);
  m.check("analysis", false);
  m.solver->factor(A);
  m.check("factorisation", true);
}

void SparseCholesky::refactorize(const Eigen::SparseMatrix<double>& A) {
  Impl& m = *impl_;
  if (!m.solver || A.rows() != m.rows) return factorize(A);
  m.reset_view();
  m.solver->factor(A);
  m.check("factorisation", true);
}

Eigen::VectorXd SparseCholesky::solve(const Eigen::VectorXd& b) const {
  if (!impl_->solver) throw std::logic_error("sparse Cholesky: solve before factorize");
  return impl_->solver->solve(b);
}

Eigen::MatrixXd SparseCholesky::solve_columns(const Eigen::MatrixXd& B) const {
  if (!impl_->solver) throw std::logic_error("sparse Cholesky: solve before factorize");
  return impl_->solver->solve(B);
}

bool SparseCholesky::has_factor_columns() const {
  if (!impl_->solver) return false;
  if (!impl_->viewed) impl_->make_view();
  return impl_->has_view;
}

FactorColumn SparseCholesky::factor_column(Eigen::Index i) const {
  if (!has_factor_columns()) throw std::logic_error("sparse Cholesky: this factor gives no columns (factor_column)");
  const Impl& m = *impl_;
  const FactorView& v = m.view;
  if (i < 0 || i >= v.n) throw std::out_of_range("sparse Cholesky: factor_column of a row out of range");
  // L x = e_k (k the pivot of row i) touches only the path of k up the elimination tree:
  // columns in ascending order, each scattering into rows of that same path.
  FactorColumn z;
  for (int j = v.pivot[static_cast<std::size_t>(i)]; j >= 0; j = m.parent[static_cast<std::size_t>(j)]) z.index.push_back(j);
  double* x = m.scratch.data();
  x[z.index[0]] = 1;
  for (const int j : z.index) {
    const int begin = v.colptr[j], end = begin + (v.count ? v.count[j] : v.colptr[j + 1] - v.colptr[j]);
    int q = begin;
    if (v.diagonal_in_column) {
      if (v.ll) x[j] /= v.value[q];
      ++q;
    }
    const double xj = x[j];
    if (xj != 0)
      for (; q < end; ++q) x[v.row[q]] -= v.value[q] * xj;
  }
  z.value.resize(z.index.size());
  for (std::size_t a = 0; a < z.index.size(); ++a) {
    const int j = z.index[a];
    double d = 1;
    if (!v.ll) d = v.diagonal ? v.diagonal[j] : v.value[v.colptr[j]];
    z.value[a] = v.ll ? x[j] : x[j] / std::sqrt(d);
    x[j] = 0;
  }
  return z;
}

double dot(const FactorColumn& a, const FactorColumn& b) {
  double s = 0;
  std::size_t p = 0, q = 0;
  while (p < a.index.size() && q < b.index.size()) {
    if (a.index[p] < b.index[q]) ++p;
    else if (b.index[q] < a.index[p]) ++q;
    else s += a.value[p++] * b.value[q++];
  }
  return s;
}

CholeskyBackend SparseCholesky::backend() const { return impl_->solver ? impl_->resolved : impl_->requested; }
Eigen::Index SparseCholesky::rows() const { return impl_->rows; }

}  // namespace moreau::fem
