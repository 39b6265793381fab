#include "fclib_cli.hpp"

#include <CLI/CLI.hpp>
#include <ostream>

#include "commands.hpp"

namespace moreau::kernel {

void add_fclib_solve_options(CLI::App& cmd, FclibSolveArgs& args) {
  cmd.add_option("problem", args.problem, "FCLib problem file (HDF5, local or global)")->required();
  cmd.add_option("--solver", args.solver, "solver plugin (default: auto)");
  cmd.add_option("--tol", args.tolerance, "tolerance on the DESIGN §1 error")->check(CLI::PositiveNumber);
  cmd.add_option("--max-iter", args.max_iterations, "maximum iterations")->check(CLI::PositiveNumber);
  cmd.add_option("--solution", args.solution, "write /solution/{r,u[,v]} to this file");
}

int command_fclib_solve(const FclibSolveArgs& args, std::ostream& out, std::ostream& err) {
  (void)args;
  (void)out;
  return guarded(err, [&]() -> int { throw RunError("fclib solve: not wired yet"); });
}

}  // namespace moreau::kernel
