#include "sparse_cholesky.hpp"

#include <Eigen/SparseCholesky>
#include <stdexcept>
#include <string>

#ifdef MOREAU_FEM_CHOLMOD
#include <dlfcn.h>

#include <Eigen/CholmodSupport>
#endif

namespace moreau::fem {
namespace {

#ifdef MOREAU_FEM_CHOLMOD
/// CHOLMOD brings libgomp (OpenMP) into the plugin that uses it, and libgomp is not made
/// to be unloaded with that plugin: it keeps memory it allocates when it loads in a global
/// of its own (LeakSanitizer reports it as a leak once the library is gone: 8 bytes at the
/// end of every run or check of a scene with an elastic body), and OpenMP worker threads
/// would be left in code no longer mapped. Kept loaded for the life of the process
/// (RTLD_NODELETE, the handle never closed), as if the program had linked it.
[[maybe_unused]] const bool gomp_kept_loaded = dlopen("libgomp.so.1", RTLD_NOW | RTLD_NOLOAD | RTLD_NODELETE) != nullptr;
#endif

using Sparse = Eigen::SparseMatrix<double>;

struct Solver {
  virtual ~Solver() = default;
  virtual void analyze(const Sparse& A) = 0;
  virtual void factor(const Sparse& A) = 0;
  virtual Eigen::ComputationInfo info() const = 0;
  /// An LDLᵀ succeeds on indefinite matrices; the caller needs positive definite ones.
  virtual bool positive_pivots() const { return true; }
  virtual Eigen::VectorXd solve(const Eigen::VectorXd& b) const = 0;
  virtual Eigen::MatrixXd solve(const Eigen::MatrixXd& B) const = 0;
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
};

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
};
#endif

std::unique_ptr<Solver> make_solver(CholeskyBackend backend) {
  switch (backend) {
    case CholeskyBackend::eigen_ldlt:
      return std::make_unique<SolverOf<Eigen::SimplicialLDLT<Sparse, Eigen::Lower, Eigen::AMDOrdering<int>>>>();
    case CholeskyBackend::eigen_llt:
      return std::make_unique<SolverOf<Eigen::SimplicialLLT<Sparse, Eigen::Lower, Eigen::AMDOrdering<int>>>>();
#ifdef MOREAU_FEM_CHOLMOD
    case CholeskyBackend::cholmod_supernodal:
      return std::make_unique<SolverOf<Eigen::CholmodSupernodalLLT<Sparse, Eigen::Lower>>>();
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
  // reference BLAS: CHOLMOD's simplicial LDLᵀ solves fastest at every size in 2D and 3D
  // (2–4× Eigen's, 1.1–2.5× CHOLMOD's supernodal, for blocks of right-hand sides),
  // factorises like the others in 2D and 1.7–3.6× slower than the supernodal one in 3D. A run
  // factorises once and solves every step (free velocity, then LHS⁻¹ H for W), so the
  // solve decides past about a thousand column solves, a hundred steps of a few contacts.
  // Without CHOLMOD, Eigen's LDLᵀ (as fast as its LLᵀ, never slower to factorise).
  return backend_available(CholeskyBackend::cholmod_simplicial) ? CholeskyBackend::cholmod_simplicial
                                                                  : CholeskyBackend::eigen_ldlt;
}

struct SparseCholesky::Impl {
  CholeskyBackend requested, resolved = CholeskyBackend::automatic;
  Eigen::Index rows = 0;
  std::unique_ptr<Solver> solver;

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
  m.solver = make_solver(m.resolved);
  m.rows = A.rows();
  m.solver->analyze(A);
  m.check("analysis", false);
  m.solver->factor(A);
  m.check("factorisation", true);
}

void SparseCholesky::refactorize(const Eigen::SparseMatrix<double>& A) {
  Impl& m = *impl_;
  if (!m.solver || A.rows() != m.rows) return factorize(A);
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

CholeskyBackend SparseCholesky::backend() const { return impl_->solver ? impl_->resolved : impl_->requested; }
Eigen::Index SparseCholesky::rows() const { return impl_->rows; }

}  // namespace moreau::fem
