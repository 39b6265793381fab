#pragma once
// `moreau fclib solve PROBLEM.hdf5 --solver NAME [--tol X] [--max-iter N] [--solution OUT.hdf5]`
#include <iosfwd>
#include <optional>
#include <string>

namespace CLI {
class App;
}

namespace moreau::kernel {

struct FclibSolveArgs {
  std::string problem;
  std::string solver = "nlgs";  // the default until the automatic solver exists
  std::optional<double> tolerance;
  std::optional<long> max_iterations;
  std::optional<std::string> solution;
};

void add_fclib_solve_options(CLI::App& cmd, FclibSolveArgs& args);
int command_fclib_solve(const FclibSolveArgs& args, std::ostream& out, std::ostream& err);

}  // namespace moreau::kernel
