// Newton's first step on FCLib files: the step `auto` estimates before paying one, from W's
// size (est0) and from the predicted fill (est1, plugins/solver/lu_fill.hpp), against the
// step Newton counts (actual_step, from r = 0 and from the file's guess), the predicted and
// the actual factors' entries, and the CPU ns of the prediction and of the step (minimum of 5).
// Run by hand (docs/solvers-history.md, i15-fill), never by ctest:
//   build/bin/moreau_bench_lu_fill corpus/problems/*.hdf5 > fill.csv
#include <chrono>
#include <cstdio>
#include <filesystem>
#include "../../kernel/fclib/fclib.hpp"
#include "../../plugins/solver/lu_fill.hpp"
#include "../../plugins/solver/work.hpp"
#include "newton_core.hpp"
using namespace moreau;
#include <ctime>
static double now() { timespec t; clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t); return t.tv_sec + 1e-9 * t.tv_nsec; }
int main(int argc, char** argv) {
  std::printf("file,warm,dim,nc,n,nnzW,est0,fill_pred,fill_act,est1,actual_step,pred_work,pred_ns,step_ns\n");
  for (int a = 1; a < argc; ++a) {
    auto prob = fclib::read(argv[a]);
    const LocalProblem& P = prob.local;
    const double n = P.dim * P.contacts(), nnz = P.W.nonZeros();
    const WorkCosts c = WorkCosts::of(P, false);
    const double e0 = WorkCosts::newton_step(nnz, n, nnz, nnz, c.product);
    double t0, pred_ns = 1e30;
    LuFill f;
    for (int k = 0; k < 5; ++k) { t0 = now(); f = predicted_lu_fill(P.W, P.dim); pred_ns = std::min(pred_ns, (now() - t0) * 1e9); }
    const double e1 = WorkCosts::newton_step(nnz, n, f.nnz_l, f.nnz_u, c.product);
    for (int warm = 0; warm < 2; ++warm) {
      if (warm && !prob.guess_r) continue;
      newton::Options o;
      o.max_iterations = 1;
      o.tolerance = 0;
      double work = 0;
      o.work = &work;
      newton::Newton nt;
      double step_ns = 1e30;
      for (int k = 0; k < 5; ++k) {
        work = 0;
        Eigen::VectorXd r = warm ? *prob.guess_r : Eigen::VectorXd::Zero(n), u;
        t0 = now();
        nt.solve(P, o, r, u);
        step_ns = std::min(step_ns, (now() - t0) * 1e9);
      }
      const double step = work - c.product - c.error;
      std::printf("%s,%d,%d,%ld,%.0f,%.0f,%.4g,%.4g,%.4g,%.4g,%.4g,%.4g,%.4g,%.4g\n",
                  std::filesystem::path(argv[a]).stem().c_str(), warm, P.dim, (long)P.contacts(), n, nnz, e0,
                  f.nnz_l + f.nnz_u, nt.factor_entries(), e1, step, f.work, pred_ns, step_ns);
    }
  }
}
