#include "console.hpp"

#include <iostream>

#include "progress.hpp"

namespace moreau::kernel {

namespace {
Progress* active = nullptr;  // one run per process
}

void set_active_progress(Progress* progress) { active = progress; }

void warn(const std::string& text) {
  if (active) active->clear_line();
  std::cerr << "warning: " << text << "\n";
  std::cerr.flush();
}

}  // namespace moreau::kernel
