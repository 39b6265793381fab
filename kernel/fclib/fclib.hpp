#pragma once
// FCLib frictional-contact problems (DESIGN §3.5): local (W, q, μ) or global
// (M, H, f, w, μ with M v = H r + f, u = Hᵀ v + w).
#include <Eigen/SparseCore>
#include <moreau/contact_problem.hpp>
#include <optional>
#include <string>
#include <vector>

namespace moreau::fclib {

struct GlobalProblem {
  int dim = 3;
  Eigen::SparseMatrix<double> M;  ///< n_dof × n_dof
  Eigen::SparseMatrix<double> H;  ///< n_dof × dim·nc
  Eigen::VectorXd f, w, mu;
};

struct Problem {
  bool global = false;
  /// What the reader had to interpret, for stderr (e.g. a mass matrix stored as one triangle).
  std::vector<std::string> notes;
  LocalProblem local;    ///< the problem itself, or the global one reduced
  GlobalProblem global_problem;
  std::optional<Eigen::VectorXd> guess_r;  ///< /guesses/1/r when present (never /solution)
};

/// How a square matrix meant to be symmetric is stored: both triangles (symmetric to
/// `relative_tolerance` × its largest entry), one triangle only, diagonal, or neither.
enum class MatrixStorage { full, upper, lower, diagonal, unsymmetric };
MatrixStorage symmetric_storage(const Eigen::SparseMatrix<double>& M, double relative_tolerance = 1e-10);
/// The symmetric matrix M stands for: M itself when symmetric (or diagonal), T + Tᵀ − diag(T)
/// when only one triangle T is stored (then `note` says so); InputError at `dataset` when M is
/// neither (never handed to a Cholesky).
Eigen::SparseMatrix<double> symmetric_matrix(const Eigen::SparseMatrix<double>& M, const std::string& dataset,
                                             const std::string& file, std::string* note);

/// Reads a problem. Faults: InputError with the file and the HDF5 path of the fault.
Problem read(const std::string& path);

/// W = Hᵀ M⁻¹ H, q = w + Hᵀ M⁻¹ f (M diagonal: directly; otherwise a sparse Cholesky).
LocalProblem reduce(const GlobalProblem& g, const std::string& file);
/// v = M⁻¹ (H r + f).
Eigen::VectorXd global_velocity(const GlobalProblem& g, const Eigen::VectorXd& r);

/// Writes /solution/r, /solution/u (and /solution/v) to `path`, through a temporary file.
void write_solution(const std::string& path, const Eigen::VectorXd& r, const Eigen::VectorXd& u,
                    const Eigen::VectorXd* v);

/// FCLib's /fclib_local/info strings (free text; FCLib readers show them, solvers ignore them).
struct ProblemInfo {
  std::string title, description, math_info;
};

/// Writes a whole local problem: /fclib_local (W in CSR, vectors q and mu, spacedim = p.dim,
/// info), then, when given, /guesses/1/{r,u} (a starting point, what `read` returns as
/// guess_r) and /solution/{r,u} (an answer for comparison, which `read` never returns).
/// u = W r + q is recomputed here. p.W must be the (dim·nc)² matrix, not left empty.
/// Written to a temporary name in the same folder, then renamed into place: a killed run
/// leaves no half-written problem.
void write_local(const std::string& path, const LocalProblem& p, const ProblemInfo& info,
                 const Eigen::VectorXd* guess_r, const Eigen::VectorXd* solution_r);

}  // namespace moreau::fclib

namespace moreau::fclib {

/// Writes a whole global problem: /fclib_global (M and H in CSR, vectors f, w and mu,
/// spacedim, info), then /guesses/1 and /solution as (r, v, u) when given, through a
/// temporary file as write_local does. `read` reads it back (reducing it to W, q).
void write_global(const std::string& path, const GlobalProblem& g, const ProblemInfo& info, const Eigen::VectorXd* guess_r,
                  const Eigen::VectorXd* solution_r);

}  // namespace moreau::fclib
