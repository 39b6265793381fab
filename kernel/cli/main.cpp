// moreau: the command line (DESIGN §3.1).
#include <CLI/CLI.hpp>
#include <iostream>

#include "commands.hpp"
#include "fclib_cli.hpp"

int main(int argc, char** argv) {
  using namespace moreau::kernel;
  CLI::App app{"moreau: non-smooth contact dynamics (Moreau-Jean) for collections of bodies in 2D and 3D"};
  app.require_subcommand(1);

  RunArgs run;
  auto* run_cmd = app.add_subcommand("run", "run a scene");
  run_cmd->add_option("scene", run.scene, "scene file (JSON, moreau-scene/1)")->required();
  run_cmd->add_option("--out", run.out, "output HDF5 file (default: the scene's output.file)");
  run_cmd->add_option("--steps", run.steps, "number of steps to run (default: the scene's duration)")
      ->check(CLI::PositiveNumber);
  run_cmd->add_option("--restart", run.restart, "continue from a frame of this output file");
  run_cmd->add_option("--frame", run.restart_frame, "with --restart: the frame (step number) to continue from "
                                                    "(default: the last complete one)");
  run_cmd->add_flag("--quiet", run.quiet, "no progress or timings on stderr");

  std::string check_scene;
  auto* check_cmd = app.add_subcommand("check", "validate a scene (every error at once)");
  check_cmd->add_option("scene", check_scene, "scene file")->required();

  bool as_json = false;
  auto* plugins_cmd = app.add_subcommand("plugins", "list every plugin by kind, with its parameters");
  plugins_cmd->add_flag("--json", as_json, "as JSON");

  FclibSolveArgs fclib;
  auto* fclib_cmd = app.add_subcommand("fclib", "FCLib frictional-contact problems");
  fclib_cmd->require_subcommand(1);
  auto* solve_cmd = fclib_cmd->add_subcommand("solve", "solve one FCLib problem; prints one JSON line");
  add_fclib_solve_options(*solve_cmd, fclib);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;  // usage errors are bad input
  }
  if (*run_cmd) return command_run(run, std::cout, std::cerr);
  if (*check_cmd) return command_check(check_scene, std::cout, std::cerr);
  if (*plugins_cmd) return command_plugins(as_json, std::cout, std::cerr);
  if (*solve_cmd) return command_fclib_solve(fclib, std::cout, std::cerr);
  return 2;
}
