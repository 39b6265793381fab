#pragma once
#include <sys/types.h>
// Runs the `moreau` executable as a user would, capturing exit code, stdout and stderr.
#include <filesystem>
#include <string>
#include <vector>

namespace moreau_test {

struct Result {
  int code = -1;
  std::string out, err;
};

/// Runs moreau with `args` (no shell), in `cwd` (default: a fresh temp folder).
Result run_moreau(const std::vector<std::string>& args, const std::filesystem::path& cwd = {});

/// Starts moreau with `args` in `cwd` in the background (its output goes to files there)
/// and returns its process id, for tests that kill runs.
pid_t start_moreau(const std::vector<std::string>& args, const std::filesystem::path& cwd);
/// SIGKILLs a run started by start_moreau and waits for it; false if it had ended first.
bool kill_moreau(pid_t pid);

/// A fresh empty folder for one test.
std::filesystem::path scratch_dir(const std::string& name);

/// Writes `text` to `dir/name` and returns the path.
std::filesystem::path write_file(const std::filesystem::path& dir, const std::string& name, const std::string& text);

}  // namespace moreau_test
