#pragma once
// The `moreau` subcommands (DESIGN §3.1). Each returns the process exit code:
// 0 success, 1 the run failed, 2 bad input.
#include <iosfwd>
#include <optional>
#include <string>

namespace moreau::kernel {

struct RunArgs {
  std::string scene;
  std::optional<std::string> out;
  std::optional<long> steps;
  std::optional<std::string> restart;
  std::optional<long> restart_frame;
  bool quiet = false;
};

int command_run(const RunArgs& args, std::ostream& out, std::ostream& err);
int command_check(const std::string& scene, std::ostream& out, std::ostream& err);
int command_plugins(bool as_json, std::ostream& out, std::ostream& err);
int command_generate(const std::string& scene, const std::string& out_path, std::ostream& out, std::ostream& err);

/// Runs `body` and maps exceptions to messages and exit codes.
template <class F>
int guarded(std::ostream& err, F&& body);

}  // namespace moreau::kernel

#include "guarded.hpp"
