// Benchmark of the sparse Cholesky backends on the θ-scheme's matrix LHS = M + h²θ²K (the
// free block, one side clamped), on structured 2D (Q4) and 3D (H8, T4) meshes from 10³ to
// 10⁵ DOFs. Prints a markdown table: analysis + factorisation processor time, solve time for one
// right-hand side and per column for a block of 64 (the W = Hᵀ LHS⁻¹ H build), memory
// the factorisation holds (heap in use after minus before, glibc mallinfo2), and the
// relative residual. Run it with nothing else heavy on the machine:
//   nice -n 19 build/bin/moreau_bench_fem_cholesky [--min-dofs N] [--max-dofs N] [--dims 2,3] [--types Q4,H8,T4]
//     [--backends eigen-ldlt,eigen-llt,cholmod-supernodal,cholmod-simplicial] [--repeat R]
#include <malloc.h>

#include <ctime>
#include <cstdio>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

#include "dof_partition.hpp"
#include "elasticity.hpp"
#include "mesh_generate.hpp"
#include "sparse_cholesky.hpp"

using namespace moreau::fem;
namespace {

/// Processor time of this process (every backend here runs on one thread): on a shared
/// machine it is far steadier than wall time.
struct Clock {
  using time_point = double;
  static double now() {
    timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
  }
};
double seconds_since(double t0) { return Clock::now() - t0; }

std::size_t heap_in_use() { return mallinfo2().uordblks + mallinfo2().hblkhd; }

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream in(s);
  for (std::string item; std::getline(in, item, ',');) out.push_back(item);
  return out;
}

bool contains(const std::vector<std::string>& list, const std::string& x) {
  for (const auto& s : list)
    if (s == x) return true;
  return false;
}

Mesh make_mesh(ElementType type, int n) {
  if (type == ElementType::Q4) return rectangle_mesh({0, 0}, {1, 1}, 1.0 / n, type);
  return box_mesh({0, 0, 0}, {1, 1, 1}, 1.0 / n, type);
}

}  // namespace

int main(int argc, char** argv) {
  double max_dofs = 1.1e5, min_dofs = 0;
  int repeat = 3;
  std::vector<std::string> dims{"2", "3"}, types{"Q4", "H8", "T4"},
      backends{"eigen-ldlt", "eigen-llt", "cholmod-supernodal", "cholmod-simplicial"};
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const auto value = [&] {
      if (i + 1 >= argc) {
        std::fprintf(stderr, "%s needs a value\n", a.c_str());
        std::exit(2);
      }
      return std::string(argv[++i]);
    };
    if (a == "--max-dofs") max_dofs = std::stod(value());
    else if (a == "--min-dofs") min_dofs = std::stod(value());
    else if (a == "--dims") dims = split(value());
    else if (a == "--types") types = split(value());
    else if (a == "--backends") backends = split(value());
    else if (a == "--repeat") repeat = std::stoi(value());
    else {
      std::fprintf(stderr, "usage: %s [--min-dofs N] [--max-dofs N] [--dims 2,3] [--types Q4,H8,T4] [--backends a,b] [--repeat R]\n", argv[0]);
      return 2;
    }
  }
  const CholeskyBackend all[] = {CholeskyBackend::eigen_ldlt, CholeskyBackend::eigen_llt,
                                 CholeskyBackend::cholmod_supernodal, CholeskyBackend::cholmod_simplicial};
  // Cells per side giving about 10³, 3·10³, 10⁴, 3·10⁴, 10⁵ DOFs.
  struct Size {
    ElementType type;
    int n;
  };
  const std::vector<Size> sizes = {{ElementType::Q4, 22}, {ElementType::Q4, 38}, {ElementType::Q4, 70},
                                   {ElementType::Q4, 122}, {ElementType::Q4, 223}, {ElementType::H8, 6},
                                   {ElementType::H8, 9},  {ElementType::H8, 14},  {ElementType::H8, 21},
                                   {ElementType::H8, 31}, {ElementType::T4, 6},   {ElementType::T4, 9},
                                   {ElementType::T4, 14}, {ElementType::T4, 21},  {ElementType::T4, 31}};
  std::printf("| mesh | DOFs | nnz(A) | backend | factor (s) | solve 1 (ms) | solve 64 (ms/col) | memory (MB) | residual |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|\n");
  for (const Size& size : sizes) {
    const std::string type_name(element_info(size.type).name);
    const std::string dim = size.type == ElementType::Q4 ? "2" : "3";
    if (!contains(types, type_name) || !contains(dims, dim)) continue;
    Mesh mesh = make_mesh(size.type, size.n);
    if (mesh.dof_count() > max_dofs || mesh.dof_count() < min_dofs) continue;
    const Material mat{200e9, 0.3, 7800, mesh.dim == 3 ? Hypothesis::solid : Hypothesis::plane_strain};
    const SparseMatrix K = stiffness_matrix(mesh, mat), M = mass_matrix(mesh, mat.density, MassKind::lumped);
    const DofPartition dofs(mesh.dof_count(), node_dofs(mesh, mesh.node_set("xmin")));
    const double h = 1e-5, theta = 0.5;
    SparseMatrix A = dofs.free_block(theta_lhs(M, SparseMatrix(M.rows(), M.cols()), K, h, theta));
    Eigen::VectorXd b(A.rows());
    for (Eigen::Index i = 0; i < b.size(); ++i) b[i] = std::sin(0.1 * i);
    Eigen::MatrixXd B(A.rows(), 64);
    for (Eigen::Index j = 0; j < 64; ++j)
      for (Eigen::Index i = 0; i < B.rows(); ++i) B(i, j) = std::cos(0.01 * i * (j + 1));
    for (CholeskyBackend backend : all) {
      if (!contains(backends, std::string(backend_name(backend))) || !backend_available(backend)) continue;
      double factor = 1e300, solve1 = 1e300, solve64 = 1e300, residual = 0;
      std::size_t memory = 0;
      for (int r = 0; r < repeat; ++r) {
        malloc_trim(0);
        const std::size_t before = heap_in_use();
        SparseCholesky chol(backend);
        auto t0 = Clock::now();
        chol.factorize(A);
        factor = std::min(factor, seconds_since(t0));
        memory = heap_in_use() - before;
        t0 = Clock::now();
        const Eigen::VectorXd x = chol.solve(b);
        solve1 = std::min(solve1, seconds_since(t0));
        t0 = Clock::now();
        const Eigen::MatrixXd X = chol.solve_columns(B);
        solve64 = std::min(solve64, seconds_since(t0) / 64);
        residual = (A * x - b).norm() / b.norm();
        if (factor > 20) break;  // one run is enough to rank a slow case
      }
      std::printf("| %s %d%s | %ld | %ld | %s | %.3f | %.2f | %.3f | %.1f | %.0e |\n", type_name.c_str(), size.n, mesh.dim == 2 ? "²" : "³",
                  static_cast<long>(A.rows()), static_cast<long>(A.nonZeros()), std::string(backend_name(backend)).c_str(),
                  factor, 1e3 * solve1, 1e3 * solve64, memory / 1048576.0, residual);
      std::fflush(stdout);
    }
  }
  return 0;
}
