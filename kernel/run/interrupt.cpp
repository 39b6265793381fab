#include "interrupt.hpp"

#include <unistd.h>

#include <csignal>

namespace moreau::kernel {

namespace {

std::atomic<int> received{0};
bool terminal = false;  // stderr is a terminal: the message replaces the progress bar's line
struct sigaction previous_int, previous_term;

extern "C" void on_signal(int sig) {
  received.store(sig);
  // Only async-signal-safe calls here: write(2), and back to the default action so that
  // a second signal ends the process.
  static const char erase[] = "\r\033[K";
  static const char msg[] = "interrupted: finishing the step under way and writing the output (again to quit at once)\n";
  if (terminal) [[maybe_unused]] const auto e = write(STDERR_FILENO, erase, sizeof erase - 1);
  [[maybe_unused]] const auto n = write(STDERR_FILENO, msg, sizeof msg - 1);
  struct sigaction dfl {};
  dfl.sa_handler = SIG_DFL;
  sigemptyset(&dfl.sa_mask);
  sigaction(sig, &dfl, nullptr);
}

}  // namespace

InterruptHandler::InterruptHandler() {
  received.store(0);
  terminal = isatty(STDERR_FILENO) != 0;
  struct sigaction sa {};
  sa.sa_handler = on_signal;
  sigemptyset(&sa.sa_mask);
  sigaction(SIGINT, &sa, &previous_int);
  sigaction(SIGTERM, &sa, &previous_term);
}

InterruptHandler::~InterruptHandler() {
  sigaction(SIGINT, &previous_int, nullptr);
  sigaction(SIGTERM, &previous_term, nullptr);
}

const std::atomic<int>& InterruptHandler::signal() { return received; }

}  // namespace moreau::kernel
