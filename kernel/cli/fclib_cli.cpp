#include "fclib_cli.hpp"

#include <CLI/CLI.hpp>
#include <chrono>
#include <filesystem>
#include <moreau/contact_error.hpp>
#include <moreau/solver.hpp>
#include <nlohmann/json.hpp>
#include <ostream>

#include "../fclib/fclib.hpp"
#include "../plugin/registry.hpp"
#include "../scene/validate.hpp"
#include "commands.hpp"

namespace moreau::kernel {

void add_fclib_solve_options(CLI::App& cmd, FclibSolveArgs& args) {
  cmd.add_option("problem", args.problem, "FCLib problem file (HDF5, local or global)")->required();
  cmd.add_option("--solver", args.solver, "solver plugin (default: nlgs)");
  cmd.add_option("--tol", args.tolerance, "tolerance on the DESIGN §1 error")->check(CLI::PositiveNumber);
  cmd.add_option("--max-iter", args.max_iterations, "maximum iterations")->check(CLI::PositiveNumber);
  cmd.add_option("--solution", args.solution, "write /solution/{r,u[,v]} to this file");
}

int command_fclib_solve(const FclibSolveArgs& args, std::ostream& out, std::ostream& err) {
  return guarded(err, [&] {
    fclib::Problem problem = fclib::read(args.problem);
    Registry reg(Registry::standard_paths({}, "."));
    const RegistryEntry& entry = reg.require(Kind::solver, args.solver, "--solver");
    nlohmann::json params = nlohmann::json::object();
    if (args.tolerance) params["tolerance"] = *args.tolerance;
    if (args.max_iterations) params["max_iterations"] = *args.max_iterations;
    std::vector<InputError> errors;
    Validation v{problem.local.dim, errors};
    nlohmann::json filled = validate_object(params, entry.registration.schema, "", v);
    if (!errors.empty()) throw InputErrors(errors);
    BuildContext ctx;
    ctx.dimension = problem.local.dim;
    auto solver = reg.create<Solver>(args.solver, Params(filled, ""), ctx, "--solver");

    const LocalProblem& P = problem.local;
    Eigen::VectorXd r = Eigen::VectorXd::Zero(P.dim * P.contacts()), u;
    const auto t0 = std::chrono::steady_clock::now();
    SolverReport rep = solver->solve(P, r, u);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    u = P.W * r + P.q;
    const double error = natural_map_error(P, r, u);  // recomputed from r, whatever the solver said
    nlohmann::ordered_json line{{"problem", std::filesystem::path(args.problem).filename().string()},
                        {"kind", problem.global ? "global" : "local"},
                        {"contacts", P.contacts()},
                        {"solver", args.solver},
                        {"tolerance", filled.value("tolerance", 0.0)},
                        {"iterations", rep.iterations},
                        {"error", error},
                        {"seconds", seconds},
                        {"converged", rep.converged && error <= filled.value("tolerance", 0.0)}};
    out << line.dump() << "\n";
    if (args.solution) {
      if (problem.global) {
        const Eigen::VectorXd vel = fclib::global_velocity(problem.global_problem, r);
        const Eigen::VectorXd ug = problem.global_problem.H.transpose() * vel + problem.global_problem.w;
        fclib::write_solution(*args.solution, r, ug, &vel);
      } else {
        fclib::write_solution(*args.solution, r, u, nullptr);
      }
    }
    return 0;
  });
}

}  // namespace moreau::kernel
