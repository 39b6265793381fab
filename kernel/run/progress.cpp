#include "progress.hpp"

#include <cstdio>
#include <string>

namespace moreau::kernel {

Progress::Progress(std::ostream& os, bool terminal, long first_step, long last_step)
    : os_(os), terminal_(terminal), first_(first_step), last_(last_step),
      start_(std::chrono::steady_clock::now()), last_draw_(start_) {}

void Progress::update(long step, double time) {
  const auto now = std::chrono::steady_clock::now();
  if (terminal_) {
    if (now - last_draw_ < std::chrono::milliseconds(100)) return;
    last_draw_ = now;
    draw(step, time);
    return;
  }
  // Not a terminal: a line at every tenth of the run, or every 10 s.
  const long span = std::max(1L, last_ - first_);
  const int decile = static_cast<int>(10 * (step - first_) / span);
  if (decile > last_decile_ || now - last_draw_ > std::chrono::seconds(10)) {
    last_decile_ = decile;
    last_draw_ = now;
    draw(step, time);
  }
}

void Progress::finish(long step, double time) {
  // The last line once: not again if update() has just drawn this step.
  if (step != drawn_step_) draw(step, time);
  if (terminal_ && drawn_step_ >= 0) {
    os_ << "\n";
    os_.flush();
  }
}

void Progress::draw(long step, double time) {
  drawn_step_ = step;
  const long span = std::max(1L, last_ - first_);
  const double frac = std::min(1.0, static_cast<double>(step - first_) / span);
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const double eta = frac > 0 ? elapsed * (1 - frac) / frac : 0;
  char buf[200];
  if (terminal_) {
    const int width = 30, filled = static_cast<int>(frac * width);
    std::string bar(filled, '#');
    bar += std::string(width - filled, '-');
    // Back to the line's start, the bar, then erase what a longer earlier line left (ESC [K).
    std::snprintf(buf, sizeof buf, "\r[%s] %5.1f%%  step %ld/%ld  t=%.4g s  %.1f s elapsed, %.1f s left\033[K", bar.c_str(),
                  100 * frac, step, last_, time, elapsed, eta);
    os_ << buf;
  } else {
    std::snprintf(buf, sizeof buf, "progress: %5.1f%%  step %ld/%ld  t=%.6g s  elapsed %.1f s\n", 100 * frac, step, last_,
                  time, elapsed);
    os_ << buf;
  }
  os_.flush();
}

void Progress::clear_line() {
  if (!terminal_ || drawn_step_ < 0) return;
  os_ << "\r\033[K";
  os_.flush();
  drawn_step_ = -1;
}

}  // namespace moreau::kernel
