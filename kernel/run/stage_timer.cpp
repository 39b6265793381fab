#include "stage_timer.hpp"

#include <cstdio>

namespace moreau::kernel {

void StageTimer::print(std::ostream& os, long steps) const {
  const double t = total();
  char line[160];
  std::snprintf(line, sizeof line, "stage %s time over %ld steps (stages with no work are skipped):\n",
                StageClock::cpu() ? "CPU" : "wall", steps);
  os << line;
  for (int i = 0; i < stage_count; ++i) {
    if (!active_[i]) continue;
    std::snprintf(line, sizeof line, "  %-24s %10.4f s %6.1f %%\n", std::string(stage_names[i]).c_str(), seconds_[i],
                  t > 0 ? 100.0 * seconds_[i] / t : 0.0);
    os << line;
    if (i == static_cast<int>(Stage::solve) && solve_assembly_ > 0) {  // not a stage: no \w+ name
      std::snprintf(line, sizeof line, "    %-22s %10.4f s\n", "(of which W assembly)", solve_assembly_);
      os << line;
    }
    if (i == static_cast<int>(Stage::solve) && solve_shadows_ > 0) {
      std::snprintf(line, sizeof line, "    %-22s %10.4f s\n", "(shadows, not counted)", solve_shadows_);
      os << line;
    }
  }
  if (hooks_ > 0) {
    std::snprintf(line, sizeof line, "  %-24s %10.4f s %6.1f %%\n", "(hooks)", hooks_, t > 0 ? 100.0 * hooks_ / t : 0.0);
    os << line;
  }
  std::snprintf(line, sizeof line, "  %-24s %10.4f s\n", "total", t);
  os << line;
}

}  // namespace moreau::kernel
