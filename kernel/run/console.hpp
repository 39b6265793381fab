#pragma once
// Messages on stderr during a run. A progress bar redrawn in place on a terminal would
// have a warning printed after its text on the same line, and a bar drawn over it; warn()
// erases the bar first (the next update draws it again below the message).
#include <string>

namespace moreau::kernel {

class Progress;

/// Prints "warning: <text>" as a line on stderr, after erasing the active progress bar.
void warn(const std::string& text);

/// The progress bar on the terminal while a run goes (set and reset by the scheduler).
void set_active_progress(Progress* progress);

}  // namespace moreau::kernel
