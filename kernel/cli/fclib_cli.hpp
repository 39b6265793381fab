#pragma once
// `moreau fclib solve PROBLEM.hdf5 --solver NAME [--tol X] [--max-iter N] [--solution OUT.hdf5]
//                     [--param KEY=VALUE]... [--repeat N] [--warm-start]`
// (DESIGN §3.1; --param, --repeat and --warm-start are extensions for the work-precision benchmark.)
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace moreau::kernel {

struct FclibSolveArgs {
  std::string problem;
  std::string solver = "auto";  // the default everywhere (scenes too)
  std::optional<double> tolerance;
  std::optional<long> max_iterations;
  std::optional<std::string> solution;
  std::vector<std::string> params;  ///< "KEY=VALUE", VALUE as JSON (or a bare string)
  long repeat = 1;                  ///< solves timed; `seconds` is their median
  bool warm_start = false;          ///< start from the file's /guesses/1/r (else r = 0)
};

void add_fclib_solve_options(CLI::App& cmd, FclibSolveArgs& args);
int command_fclib_solve(const FclibSolveArgs& args, std::ostream& out, std::ostream& err);

}  // namespace moreau::kernel
