#pragma once
// Progress on stderr: a bar redrawn in place on a terminal, periodic lines otherwise
// (logs, CI).
#include <chrono>
#include <ostream>

namespace moreau::kernel {

class Progress {
 public:
  Progress(std::ostream& os, bool terminal, long first_step, long last_step);
  void update(long step, double time);
  void finish(long step, double time);

 private:
  void draw(long step, double time, bool final);
  std::ostream& os_;
  bool terminal_;
  long first_, last_;
  std::chrono::steady_clock::time_point start_, last_draw_;
  int last_decile_ = -1;
};

}  // namespace moreau::kernel
