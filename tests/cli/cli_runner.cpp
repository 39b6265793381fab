#include "cli_runner.hpp"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fstream>
#include <sstream>
#include <stdexcept>

extern char** environ;

namespace moreau_test {

namespace fs = std::filesystem;

fs::path scratch_dir(const std::string& name) {
  fs::path d = fs::temp_directory_path() / ("moreau_cli_" + name + "_" + std::to_string(getpid()));
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

fs::path write_file(const fs::path& dir, const std::string& name, const std::string& text) {
  fs::path p = dir / name;
  std::ofstream(p) << text;
  return p;
}

static std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

/// Starts moreau with `args` in `cwd`, stdout and stderr to files there; returns its pid.
static pid_t spawn(const std::vector<std::string>& args, const fs::path& cwd, const fs::path& out, const fs::path& err) {
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_addopen(&fa, 1, out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&fa, 2, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&fa, 0, "/dev/null", O_RDONLY, 0);
  std::vector<std::string> all{MOREAU_EXE};
  all.insert(all.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& a : all) argv.push_back(a.data());
  argv.push_back(nullptr);
  // posix_spawn has no chdir action in glibc 2.36's portable API: change and restore.
  const fs::path old = fs::current_path();
  fs::current_path(cwd);
  pid_t pid;
  const int rc = posix_spawn(&pid, MOREAU_EXE, &fa, nullptr, argv.data(), environ);
  fs::current_path(old);
  posix_spawn_file_actions_destroy(&fa);
  if (rc != 0) throw std::runtime_error("cannot start " MOREAU_EXE);
  return pid;
}

Result run_moreau(const std::vector<std::string>& args, const fs::path& cwd_in) {
  const fs::path cwd = cwd_in.empty() ? scratch_dir("run") : cwd_in;
  const fs::path out = cwd / ".stdout", err = cwd / ".stderr";
  const pid_t pid = spawn(args, cwd, out, err);
  int status = 0;
  waitpid(pid, &status, 0);
  Result r;
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  r.out = slurp(out);
  r.err = slurp(err);
  fs::remove(out);
  fs::remove(err);
  return r;
}

pid_t start_moreau(const std::vector<std::string>& args, const fs::path& cwd) {
  return spawn(args, cwd, cwd / ".bg_stdout", cwd / ".bg_stderr");
}

bool kill_moreau(pid_t pid) {
  kill(pid, SIGKILL);
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFSIGNALED(status);
}

}  // namespace moreau_test
