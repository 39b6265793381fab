// The solver corpus benchmark (issue 15, docs/solvers.md "Corpus and guarantee"): every
// solver on every FCLib problem given, cold (r = 0) and warm (the file's /guesses/1/r), at
// each tolerance. Rounds are interleaved (round k solves every (problem, solver) once
// before round k + 1 starts on that problem) and the time kept is the median over the
// rounds, so that the load of the shared machine hits every solver alike; times are the
// solving thread's CPU time (solves under 20 ms are repeated and averaged). Each solve runs
// in a forked child with a time limit (a solver that needs 10⁵ sweeps on 3·10⁴ contacts
// would otherwise hold the benchmark for an hour); a solve that fails or times out is not
// repeated. The child measures the solve alone (fresh solver object, problem read once in
// the parent). Prints one CSV line per (problem, start, tolerance, solver):
//   problem,warm,contacts,dim,tolerance,solver,iterations,error,seconds,converged,repeats,work
// (work: the solve's counted work, SolverReport::work; 0 for solvers that do not count it),
// problem features on `#` lines, and at the end, on `#` lines, the guarantee measured both
// ways in this one run: per problem and tolerance, auto's CPU time over the fastest of its
// members (nlgs, apgd, newton, admm) and over the fastest of all solvers, next to auto's
// counted work over the least work of its members; then how well counted work predicts CPU
// time (ns of CPU per counted unit, per solver). docs/solvers.md "Corpus and guarantee".
//
//   moreau_bench_portfolio [--tolerances 1e-4,1e-8] [--repeat 3] [--timeout 10]
//                          [--solvers nlgs,psor,apgd,admm,newton,prox,auto] FILE.hdf5...
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <Eigen/SparseLU>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <map>
#include <moreau/contact_error.hpp>
#include <moreau/solver.hpp>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "kernel/fclib/fclib.hpp"
#include "registered_solver.hpp"

namespace {

std::unique_ptr<moreau::Solver> make(const std::string& name, double tol, long max_it) {
  nlohmann::json params = {{"tolerance", tol}, {"max_iterations", max_it}};
  return solver_cases::registered_solver(name, params, name);
}

/// The iteration caps of scripts/work_precision.py: cheap iterations may be many, a Newton
/// step costs a factorisation.
long max_iterations(const std::string& s) { return s == "newton" ? 1000 : 100000; }

struct Outcome {
  long iterations = 0;
  double error = NAN, seconds = NAN, work = 0;
  bool converged = false, finished = false;  ///< finished: within the time limit
};

/// CPU time of this thread: the machine is shared, and wall time would count the time other
/// processes held the core.
double thread_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

constexpr double min_time = 0.02;

/// One solve in a forked child, killed after `timeout` seconds.
Outcome solve_forked(const moreau::LocalProblem& P, const Eigen::VectorXd& r0, const std::string& solver, double tol,
                     double timeout) {
  int fd[2];
  if (pipe(fd) != 0) throw std::runtime_error("pipe");
  const pid_t pid = fork();
  if (pid == 0) {
    close(fd[0]);
    alarm(static_cast<unsigned>(std::ceil(timeout)));
    // Solves of a few microseconds are repeated (each by a fresh solver, from the same
    // start) until `min_time` of CPU time has been spent; the time is their mean.
    double secs = 0;
    int count = 0;
    moreau::SolverReport rep;
    do {
      auto s = make(solver, tol, max_iterations(solver));
      Eigen::VectorXd r = r0, u;
      const double t0 = thread_seconds();
      rep = s->solve(P, r, u);
      secs += thread_seconds() - t0;
      ++count;
    } while (secs < min_time && count < 100000);
    double out[5] = {static_cast<double>(rep.iterations), rep.error, secs / count, rep.converged ? 1.0 : 0.0, rep.work};
    if (write(fd[1], out, sizeof out) != sizeof out) _exit(3);
    _exit(0);
  }
  close(fd[1]);
  double in[5];
  Outcome o;
  const ssize_t got = read(fd[0], in, sizeof in);
  close(fd[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  if (got == sizeof in && WIFEXITED(status) && WEXITSTATUS(status) == 0) {
    o.iterations = static_cast<long>(in[0]);
    o.error = in[1];
    o.seconds = in[2];
    o.converged = in[3] > 0;
    o.work = in[4];
    o.finished = true;
  }
  return o;
}

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream ss(s);
  std::string x;
  while (std::getline(ss, x, ',')) out.push_back(x);
  return out;
}

std::string stem(const std::string& path) {
  std::string f = path.substr(path.find_last_of('/') + 1);
  return f.substr(0, f.rfind('.'));
}

struct Row {
  std::string problem;
  double tol;
  std::string solver;
  bool converged;
  double seconds, work;
};

bool member(const std::string& s) { return s == "nlgs" || s == "apgd" || s == "newton" || s == "admm"; }

double median(std::vector<double> v) {
  if (v.empty()) return NAN;
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

/// The guarantee both ways (CPU time and counted work) and the cost model's fit, from one run.
void summary(const std::vector<Row>& rows) {
  std::printf("# guarantee: auto over the fastest member (CPU) and over the least member work (counted), one run\n");
  std::printf("# %-44s %6s  %-7s %10s %6s  %-7s %10s %6s  %-7s %10s %6s\n", "problem", "tol", "members", "CPU s", "auto/",
              "all", "CPU s", "auto/", "work", "units", "auto/");
  std::map<double, std::vector<double>> cpu, all, work;
  std::vector<double> agree;  // auto's CPU-time ratio over its counted-work ratio, per problem
  std::map<std::string, std::vector<double>> ns;  // ns of CPU per counted unit, per solver
  for (std::size_t i = 0; i < rows.size();) {
    std::size_t j = i;
    while (j < rows.size() && rows[j].problem == rows[i].problem && rows[j].tol == rows[i].tol) ++j;
    const Row* fast = nullptr;
    const Row* fast_all = nullptr;
    const Row* least = nullptr;
    const Row* a = nullptr;
    for (std::size_t k = i; k < j; ++k) {
      const Row& r = rows[k];
      if (r.converged && r.work > 0 && r.seconds > 0) ns[r.solver].push_back(1e9 * r.seconds / r.work);
      if (r.solver == "auto") {
        a = &r;
        continue;
      }
      if (!r.converged) continue;
      if (!fast_all || r.seconds < fast_all->seconds) fast_all = &r;
      if (!member(r.solver)) continue;
      if (!fast || r.seconds < fast->seconds) fast = &r;
      if (!least || r.work < least->work) least = &r;
    }
    if (a && fast) {
      const double rc = a->converged ? a->seconds / fast->seconds : INFINITY;
      const double ra = a->converged ? a->seconds / fast_all->seconds : INFINITY;
      const double rw = a->converged && least->work > 0 ? a->work / least->work : INFINITY;
      if (std::isfinite(rc) && std::isfinite(rw)) agree.push_back(rc / rw);
      cpu[rows[i].tol].push_back(rc);
      all[rows[i].tol].push_back(ra);
      work[rows[i].tol].push_back(rw);
      std::printf("# %-44s %6g  %-7s %10.3g %6.2f  %-7s %10.3g %6.2f  %-7s %10.3g %6.2f\n", rows[i].problem.c_str(), rows[i].tol,
                  fast->solver.c_str(), fast->seconds, rc, fast_all->solver.c_str(), fast_all->seconds, ra, least->solver.c_str(),
                  least->work, rw);
    }
    i = j;
  }
  for (const auto& [tol, v] : cpu) {
    const auto& w = work[tol];
    const auto& va = all[tol];
    auto within = [](const std::vector<double>& x, double k) { return std::count_if(x.begin(), x.end(), [k](double y) { return y <= k; }); };
    std::printf("# tol %g: %zu problems solved by some member; auto / fastest member CPU: median %.2f worst %.2f, within 1.5x %ld;"
                " / fastest of all CPU: median %.2f worst %.2f; auto / least member work: median %.2f worst %.2f, within 1.5x %ld\n",
                tol, v.size(), median(v), *std::max_element(v.begin(), v.end()), within(v, 1.5), median(va),
                *std::max_element(va.begin(), va.end()), median(w), *std::max_element(w.begin(), w.end()), within(w, 1.5));
  }
  if (!agree.empty())
    std::printf("# auto's CPU-time ratio / its counted-work ratio over %zu problem-tolerance pairs: median %.2f [%.2f, %.2f]\n",
                agree.size(), median(agree), *std::min_element(agree.begin(), agree.end()),
                *std::max_element(agree.begin(), agree.end()));
  std::printf("# CPU ns per counted unit (converged solves; 1 = the model exactly): solver median [min, max]\n");
  for (const auto& [s, v] : ns)
    std::printf("#   %-8s %.2f [%.2f, %.2f] over %zu\n", s.c_str(), median(v), *std::min_element(v.begin(), v.end()),
                *std::max_element(v.begin(), v.end()), v.size());
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<double> tols = {1e-4, 1e-8};
  std::vector<std::string> solvers = {"nlgs", "psor", "apgd", "admm", "newton", "prox", "auto"};
  int repeat = 3;
  double timeout = 10;
  std::vector<std::string> files;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto next = [&]() -> std::string {
      if (i + 1 >= argc) throw std::runtime_error(a + " needs a value");
      return argv[++i];
    };
    if (a == "--tolerances") {
      tols.clear();
      for (const auto& t : split(next())) tols.push_back(std::stod(t));
    } else if (a == "--solvers") {
      solvers = split(next());
    } else if (a == "--repeat") {
      repeat = std::stoi(next());
    } else if (a == "--timeout") {
      timeout = std::stod(next());
    } else if (a.rfind("--", 0) == 0) {
      std::fprintf(stderr, "usage: %s [--tolerances 1e-4,1e-8] [--repeat 3] [--timeout 10] [--solvers a,b] FILE...\n", argv[0]);
      return 2;
    } else {
      files.push_back(a);
    }
  }
  std::printf("problem,warm,contacts,dim,tolerance,solver,iterations,error,seconds,converged,repeats,work\n");
  std::vector<Row> rows;
  for (const auto& file : files) {
    const moreau::fclib::Problem prob = moreau::fclib::read(file);
    const moreau::LocalProblem& P = prob.local;
    const Eigen::Index n = P.dim * P.contacts();
    for (bool warm : {false, true}) {
      if (warm && !(prob.guess_r && prob.guess_r->size() == n)) continue;
      const Eigen::VectorXd r0 = warm ? *prob.guess_r : Eigen::VectorXd::Zero(n);
      {  // features: size, W's fill and its LU's (as Newton factorises it), friction, the start's error
        Eigen::VectorXd u = P.W * r0 + P.q;
        Eigen::SparseMatrix<double> M = P.W;
        for (Eigen::Index i = 0; i < n; ++i) M.coeffRef(i, i) += 1e-6 * (1 + std::fabs(P.W.coeff(i, i)));
        M.makeCompressed();
        Eigen::SparseLU<Eigen::SparseMatrix<double>> lu;
        lu.analyzePattern(M);
        lu.factorize(M);
        std::printf("# %s%s contacts %ld dim %d nnzW %ld nnzL %ld nnzU %ld mu_mean %.3g mu_max %.3g start_error %.3e\n",
                    stem(file).c_str(), warm ? "+warm" : "", static_cast<long>(P.contacts()), P.dim,
                    static_cast<long>(P.W.nonZeros()), static_cast<long>(lu.nnzL()), static_cast<long>(lu.nnzU()),
                    P.contacts() ? P.mu.mean() : 0.0, P.contacts() ? P.mu.maxCoeff() : 0.0, moreau::natural_map_error(P, r0, u));
      }
      for (double tol : tols) {
        std::map<std::string, std::vector<Outcome>> runs;
        std::map<std::string, bool> done;
        for (int k = 0; k < repeat; ++k)
          for (const auto& s : solvers) {
            if (done[s]) continue;
            Outcome o = solve_forked(P, r0, s, tol, timeout);
            runs[s].push_back(o);
            if (!o.finished || !o.converged) done[s] = true;  // a failure is not repeated
          }
        for (const auto& s : solvers) {
          const auto& rs = runs[s];
          std::vector<double> t;
          for (const auto& o : rs)
            if (o.finished) t.push_back(o.seconds);
          std::sort(t.begin(), t.end());
          const Outcome& last = rs.back();
          const double med = t.empty() ? NAN : t[t.size() / 2];
          std::printf("%s%s,%d,%ld,%d,%g,%s,%ld,%.6e,%.6e,%d,%zu,%.6e\n", stem(file).c_str(), warm ? "+warm" : "", warm ? 1 : 0,
                      static_cast<long>(P.contacts()), P.dim, tol, s.c_str(), last.iterations, last.error,
                      last.finished ? med : timeout, last.converged ? 1 : 0, t.size(), last.work);
          rows.push_back({stem(file) + (warm ? "+warm" : ""), tol, s, last.finished && last.converged, med, last.work});
          std::fflush(stdout);
        }
      }
    }
  }
  summary(rows);
  return 0;
}
