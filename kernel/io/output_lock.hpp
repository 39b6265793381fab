#pragma once
// OUT.h5.lock: one run at a time writes an output file. A second run given the same
// output (or continuing it with --restart) is refused at the start instead of replacing
// the first one's frames folder under it. The lock is an flock(2) on the file, so a run
// killed with SIGKILL releases it with its process; the file itself is removed when the
// writer is done (a killed run leaves it behind, harmless: nobody holds it).
#include <string>

namespace moreau::io {

class OutputLock {
 public:
  OutputLock() = default;
  /// Takes the lock of output file `path`. InputError naming `path` if another process
  /// holds it (with that process's id) or if the lock cannot be created there.
  static OutputLock acquire(const std::string& path);
  OutputLock(OutputLock&& o) noexcept;
  OutputLock& operator=(OutputLock&& o) noexcept;
  OutputLock(const OutputLock&) = delete;
  OutputLock& operator=(const OutputLock&) = delete;
  ~OutputLock();

  /// The lock file of output `path`.
  static std::string file_of(const std::string& path) { return path + ".lock"; }

 private:
  void release();
  std::string file_;
  int fd_ = -1;
};

}  // namespace moreau::io
