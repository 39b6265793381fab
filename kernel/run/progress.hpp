#pragma once
// Progress on stderr: a bar redrawn in place on a terminal, periodic lines otherwise
// (logs, CI). The bar erases the rest of its line at each redraw, so a shorter line leaves
// nothing of a longer one; the last line (100 %, or where a run stopped) is printed once.
#include <chrono>
#include <ostream>

namespace moreau::kernel {

class Progress {
 public:
  Progress(std::ostream& os, bool terminal, long first_step, long last_step);
  void update(long step, double time);
  /// The last line (unless just drawn for this step), and on a terminal the end of the bar's line.
  void finish(long step, double time);
  /// On a terminal: erases the bar, so that a message can be printed on a clean line (the
  /// next update() draws it again).
  void clear_line();

 private:
  void draw(long step, double time);
  std::ostream& os_;
  bool terminal_;
  long first_, last_;
  std::chrono::steady_clock::time_point start_, last_draw_;
  int last_decile_ = -1;
  long drawn_step_ = -1;  ///< the step of the line on screen (−1: none)
};

}  // namespace moreau::kernel
