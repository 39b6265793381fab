#include <unistd.h>

#include <csignal>

#include <cstdlib>
#include <filesystem>
#include <ostream>

#include "../run/interrupt.hpp"
#include "../run/output_sink.hpp"
#include "../run/scheduler.hpp"
#include "../scene/builder.hpp"
#include "commands.hpp"

namespace moreau::kernel {

namespace {

/// A path as one shell word (quoted when it holds anything but plain characters).
std::string shell_word(const std::string& s) {
  const bool plain = !s.empty() && s.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-./+,:=@") ==
                                       std::string::npos;
  if (plain) return s;
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

/// An environment variable's text ("" when unset).
std::string environment(const char* name) {
  const char* v = std::getenv(name);
  return v ? v : "";
}

/// MOREAU_SHADOW_REPORT: where the shadow solvers' table goes as JSON; checked before the
/// run, so that a long run does not end unable to write it.
std::string shadow_report_path(bool shadows) {
  const std::string path = environment("MOREAU_SHADOW_REPORT");
  const std::string var = "MOREAU_SHADOW_REPORT (environment variable)";
  if (path.empty()) return path;
  if (!shadows) throw InputError("", "names a report file, but MOREAU_SHADOW_SOLVERS names no shadow solvers", var);
  const std::filesystem::path dir = std::filesystem::absolute(path).parent_path();
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec)) throw InputError("", "no folder " + dir.string() + " for " + path, var);
  return path;
}

}  // namespace

int command_run(const RunArgs& args, std::ostream& out, std::ostream& err) {
  return guarded(err, [&] {
    if (args.out && args.out->empty()) throw InputError("", "--out: expected a file name, got an empty string");
    auto world = build_world(args.scene, args.out.value_or(""), environment("MOREAU_SHADOW_SOLVERS"));
    const ShadowSolvers* shadows = world->contacts ? world->contacts->shadows.get() : nullptr;
    const std::string shadow_report = shadow_report_path(shadows != nullptr);
    const std::string path = args.out ? *args.out : world->output.file;
    RunOptions opt;
    std::optional<long> continue_after;
    bool copy_first = false;
    if (args.restart) {
      opt.first_step = load_restart(*world, *args.restart, args.restart_frame);
      // Continuing in the same file: its frame of the restart step is there already.
      // Into another file: a new file that starts with the restart frame, copied.
      std::error_code ec;
      if (std::filesystem::equivalent(*args.restart, path, ec)) continue_after = opt.first_step;
      else copy_first = true;
      opt.write_first_frame = false;
    }
    if (args.steps) opt.steps = *args.steps;
    ProblemExport* exporter = world->contacts ? world->contacts->exporter.get() : nullptr;
    if (exporter) exporter->prepare();  // before the output: an unusable folder is bad input
    std::unique_ptr<FrameSink> sink;
    if (copy_first) {
      bool copied = false;
      sink = open_output_from(*world, path, *args.restart, opt.first_step, copied);
      opt.write_first_frame = !copied;  // a file of an earlier format: written from the state
    } else {
      sink = open_output(*world, path, continue_after);
    }
    opt.sink = sink.get();
    if (!args.quiet) {
      opt.progress = &err;
      opt.progress_terminal = isatty(STDERR_FILENO) != 0;
    }
    Scheduler scheduler(*world);
    InterruptHandler interrupts;  // Ctrl-C: stop after the step under way, output complete
    opt.interrupt = &InterruptHandler::signal();
    RunSummary sum = scheduler.run(opt);
    if (world->contacts) {  // misses are said even with --quiet; a clean run only without it
      const SolveLog& log = world->contacts->solve_log;
      if (log.misses() > 0 || !args.quiet) log.print_summary(err);
    }
    if (!args.quiet) {
      sum.timer.print(err, sum.last_step - sum.first_step);
      if (sum.stopped_by_hook) err << "stopped by a hook: " << sum.stop_reason << "\n";
    }
    if (shadows) {
      err.flush();  // the table follows the stage times on a terminal
      shadows->print(out);
      if (!shadow_report.empty()) shadows->write_json(shadow_report, args.scene, sum.last_step - sum.first_step);
    }
    out << "wrote " << std::filesystem::absolute(path).string() << " (steps " << sum.first_step << " to "
        << sum.last_step << ", t = " << static_cast<double>(sum.last_step) * world->h << " s)\n";
    if (exporter) out << exporter->summary() << "\n";
    if (sum.interrupted_by) {
      err << "interrupted (" << (sum.interrupted_by == SIGINT ? "Ctrl-C" : "SIGTERM") << ") after step " << sum.last_step
          << ": " << path << " is complete up to it; continue with:\n  moreau run " << shell_word(args.scene)
          << (args.out ? " --out " + shell_word(*args.out) : std::string()) << " --restart " << shell_word(path) << "\n";
      return 128 + sum.interrupted_by;
    }
    return 0;
  });
}

}  // namespace moreau::kernel
