// moreau: the command line (DESIGN §3.1).
#include <CLI/CLI.hpp>
#include <iostream>
#include <moreau/version.hpp>

#include "../io/output_writer.hpp"
#include "../text/did_you_mean.hpp"
#include "commands.hpp"
#include "fclib_cli.hpp"
#include "guarded.hpp"

namespace {

/// What `moreau --version` prints: the program, and the versions of its contracts.
std::string version_text() {
  return std::string("moreau ") + MOREAU_VERSION + " (plugin ABI " + std::to_string(MOREAU_ABI_VERSION) + ", SDK " +
         MOREAU_SDK_VERSION + ", built with " + MOREAU_BUILD_ID + "; scene format moreau-scene/1, output " + moreau::io::output_format + ")";
}

/// After a parse error: "did you mean" for a mistyped command or option, if one is close.
/// True when it named an unknown command (CLI11's own "A subcommand is required" would then
/// only contradict it).
bool suggest(const CLI::App& app, int argc, char** argv) {
  const CLI::App* in = &app;
  for (int i = 1; i < argc; ++i) {
    const std::string word = argv[i];
    if (word.rfind("--", 0) == 0) {
      const std::string name = word.substr(0, word.find('='));
      std::vector<std::string> options;
      for (const auto* o : in->get_options())
        for (const auto& l : o->get_lnames()) options.push_back("--" + l);
      if (std::find(options.begin(), options.end(), name) == options.end()) {
        const std::string hint = moreau::kernel::did_you_mean(name, options);
        if (!hint.empty()) std::cerr << "unknown option " << name << hint << "\n";
      }
      continue;
    }
    if (word.rfind('-', 0) == 0) {
      // A short option from another program's habits (`-o`): the long one it stands for,
      // when exactly one begins with that letter.
      if (word.size() < 2 || in->get_option_no_throw(word) != nullptr) continue;
      std::vector<std::string> matches;
      for (const auto* o : in->get_options())
        for (const auto& l : o->get_lnames())
          if (l[0] == word[1]) matches.push_back("--" + l);
      if (matches.size() == 1) std::cerr << "unknown option " << word << "; did you mean \"" << matches[0] << "\"?\n";
      continue;
    }
    // The first word that is not an option names the command (then a subcommand of it).
    std::vector<std::string> names;
    for (const auto* sub : in->get_subcommands({})) names.push_back(sub->get_name());
    if (names.empty()) continue;  // a positional argument (a file)
    const auto* next = std::find(names.begin(), names.end(), word) != names.end() ? in->get_subcommand(word) : nullptr;
    if (!next) {
      const std::string hint = moreau::kernel::did_you_mean(word, names, '\'');
      std::cerr << "unknown command '" << word << "'" << (hint.empty() ? "" : hint) << " (commands:";
      for (const auto& n : names) std::cerr << " " << n;
      std::cerr << ")\n";
      return true;
    }
    in = next;
  }
  return false;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace moreau::kernel;
  install_process_guards();
  CLI::App app{"moreau: non-smooth contact dynamics (Moreau-Jean) for collections of bodies in 2D and 3D"};
  app.require_subcommand(1);
  app.set_version_flag("--version", version_text(), "print the version of moreau and of its formats, then exit");

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

  std::string generate_scene, generate_out;
  auto* generate_cmd = app.add_subcommand("generate", "run a scene's generators and write it as a plain scene");
  generate_cmd->add_option("scene", generate_scene, "scene file with `generators`")->required();
  generate_cmd->add_option("--out", generate_out, "the scene with the generated bodies listed (JSON)")->required();

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
    if (e.get_exit_code() != 0 && suggest(app, argc, argv)) {
      std::cerr << "Run with --help for more information.\n";
      return 2;
    }
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;  // usage errors are bad input
  }
  if (*run_cmd) return command_run(run, std::cout, std::cerr);
  if (*check_cmd) return command_check(check_scene, std::cout, std::cerr);
  if (*plugins_cmd) return command_plugins(as_json, std::cout, std::cerr);
  if (*generate_cmd) return command_generate(generate_scene, generate_out, std::cout, std::cerr);
  if (*solve_cmd) return command_fclib_solve(fclib, std::cout, std::cerr);
  return 2;
}
