#include "fclib_cli.hpp"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <moreau/contact_error.hpp>
#include <moreau/solver.hpp>
#include <nlohmann/json.hpp>
#include <ostream>

#include "../fclib/fclib.hpp"
#include "../plugin/boundary.hpp"
#include "../plugin/registry.hpp"
#include "../scene/json_file.hpp"
#include "../scene/validate.hpp"
#include "commands.hpp"

namespace moreau::kernel {

namespace {

/// The solver parameters of the command line as one JSON object, before schema validation.
/// A VALUE that is not valid JSON is taken as a string, so `ordering=reverse` needs no quotes.
nlohmann::json solver_params(const FclibSolveArgs& args) {
  nlohmann::json params = nlohmann::json::object();
  for (const std::string& kv : args.params) {
    const auto eq = kv.find('=');
    if (eq == std::string::npos || eq == 0)
      throw InputError("", "--param \"" + kv + "\": expected KEY=VALUE (VALUE as JSON, or a string)");
    const std::string key = kv.substr(0, eq), text = kv.substr(eq + 1);
    if (params.contains(key)) throw InputError("", "--param " + key + " given twice");
    // Valid JSON goes through the kernel's strict reader (duplicate keys, depth, range).
    params[key] = nlohmann::json::accept(text) ? parse_json(text, "--param " + key) : nlohmann::json(text);
  }
  // Two spellings of one setting would leave the user guessing which one won: refuse.
  auto set = [&](const char* key, const char* option, const nlohmann::json& value) {
    if (params.contains(key)) throw InputError("", std::string("--param ") + key + " and " + option + " both given");
    params[key] = value;
  };
  if (args.tolerance) set("tolerance", "--tol", *args.tolerance);
  if (args.max_iterations) set("max_iterations", "--max-iter", *args.max_iterations);
  return params;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

/// Validates the solver parameters, solves (`--repeat` times) and prints the line.
int solve_with(Registry& reg, const fclib::Problem& problem, const FclibSolveArgs& args, std::ostream& out) {
  const RegistryEntry& entry = reg.require(Kind::solver, args.solver, "--solver");
  std::vector<InputError> errors;
  Validation v{problem.local.dim, errors};
  nlohmann::json filled = validate_object(solver_params(args), entry.registration.schema, "", v);
  if (!errors.empty()) {
    // The pointers are relative to the solver's parameters: say whose.
    for (auto& e : errors) e = e.with_file("solver \"" + args.solver + "\" parameters");
    throw InputErrors(errors);
  }
  BuildContext ctx;
  ctx.dimension = problem.local.dim;

  const LocalProblem& P = problem.local;
  if (args.warm_start && !problem.guess_r)
    throw InputError("/guesses/1/r", "--warm-start: the file has no starting point of the right size", args.problem);
  const Eigen::VectorXd r0 = args.warm_start ? *problem.guess_r : Eigen::VectorXd::Zero(P.dim * P.contacts());
  Eigen::VectorXd r, u;
  SolverReport rep;
  std::vector<double> times;
  // A fresh solver each time, so that no run profits from what an earlier one cached.
  for (long k = 0; k < args.repeat; ++k) {
    auto solver = reg.create<Solver>(args.solver, Params(filled, ""), ctx, "--solver");
    r = r0;
    const auto t0 = std::chrono::steady_clock::now();
    rep = solver->solve(P, r, u);
    times.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  u = P.W * r + P.q;
  const double error = natural_map_error(P, r, u);  // recomputed from r, whatever the solver said
  nlohmann::ordered_json line{{"problem", std::filesystem::path(args.problem).filename().string()},
                              {"kind", problem.global ? "global" : "local"},
                              {"contacts", P.contacts()},
                              {"solver", args.solver},
                              {"tolerance", filled.value("tolerance", 0.0)},
                              {"iterations", rep.iterations},
                              {"error", error},
                              {"seconds", median(times)},
                              {"converged", rep.converged && error <= filled.value("tolerance", 0.0)},
                              {"repeats", args.repeat},
                              {"work", rep.work}};
  if (args.warm_start) line["warm_start"] = true;
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
}
}  // namespace

void add_fclib_solve_options(CLI::App& cmd, FclibSolveArgs& args) {
  cmd.add_option("problem", args.problem, "FCLib problem file (HDF5, local or global)")->required();
  cmd.add_option("--solver", args.solver, "solver plugin (default: auto, as in scenes)");
  cmd.add_option("--tol", args.tolerance, "tolerance on the DESIGN §1 error")->check(CLI::PositiveNumber);
  cmd.add_option("--max-iter", args.max_iterations, "maximum iterations")->check(CLI::PositiveNumber);
  cmd.add_option("--solution", args.solution, "write /solution/{r,u[,v]} to this file");
  cmd.add_option("--param", args.params,
                 "KEY=VALUE: any parameter of the solver's schema (see `moreau plugins`); VALUE is JSON, "
                 "or a string if not valid JSON; repeatable")
      ->take_all()
      ->allow_extra_args(false);
  cmd.add_option("--repeat", args.repeat,
                 "solve N times from r = 0, each with a fresh solver; `seconds` is the median time")
      ->check(CLI::PositiveNumber);
  cmd.add_flag("--warm-start", args.warm_start,
               "start from the file's /guesses/1/r (a time step's warm start, written by export_problems) instead of r = 0");
}

int command_fclib_solve(const FclibSolveArgs& args, std::ostream& out, std::ostream& err) {
  return guarded(err, [&] {
    fclib::Problem problem = fclib::read(args.problem);
    for (const std::string& note : problem.notes) err << "note: " << note << "\n";
    Registry reg(Registry::standard_paths({}, "."));
    // The solver's exceptions are turned into the kernel's before `reg` unloads it.
    try {
      return solve_with(reg, problem, args, out);
    } catch (...) {
      rethrow_kernel_owned(plugin_label(Kind::solver, args.solver, "--solver"));
    }
  });
}

}  // namespace moreau::kernel
