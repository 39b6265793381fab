#include "output_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <moreau/error.hpp>
#include <utility>

namespace moreau::io {

OutputLock OutputLock::acquire(const std::string& path) {
  OutputLock lock;
  lock.file_ = file_of(path);
  for (;;) {
    const int fd = ::open(lock.file_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd < 0) {
      const int e = errno;
      std::error_code ec;
      const auto parent = std::filesystem::absolute(path, ec).parent_path();
      const std::string why = !std::filesystem::is_directory(parent, ec) ? "its folder " + parent.string() + " does not exist"
                                                                          : std::string(std::strerror(e));
      throw InputError("", "cannot create the output file: " + why, path);
    }
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
      char pid[32] = {};
      const ssize_t n = ::pread(fd, pid, sizeof pid - 1, 0);
      ::close(fd);
      std::string who = n > 0 ? std::string(pid, static_cast<std::size_t>(n)) : std::string();
      while (!who.empty() && (who.back() == '\n' || who.back() == ' ')) who.pop_back();
      throw InputError("", "another moreau run" + (who.empty() ? std::string() : " (process " + who + ")") +
                               " is writing this output file (lock " + lock.file_ +
                               "); wait for it to end, or write elsewhere with --out",
                       path);
    }
    // The previous holder removes the file when done: if it did so between our open and
    // our flock, we hold a lock on a file nobody else will open. Start again.
    struct stat held, now;
    if (::fstat(fd, &held) == 0 && ::stat(lock.file_.c_str(), &now) == 0 && held.st_ino == now.st_ino &&
        held.st_dev == now.st_dev) {
      const std::string pid = std::to_string(::getpid()) + "\n";
      if (::ftruncate(fd, 0) == 0 && ::pwrite(fd, pid.data(), pid.size(), 0) < 0) {
        // The process id is only for the message of a second run: not worth failing for.
      }
      lock.fd_ = fd;
      return lock;
    }
    ::close(fd);
  }
}

OutputLock::OutputLock(OutputLock&& o) noexcept : file_(std::move(o.file_)), fd_(std::exchange(o.fd_, -1)) {}

OutputLock& OutputLock::operator=(OutputLock&& o) noexcept {
  if (this != &o) {
    release();
    file_ = std::move(o.file_);
    fd_ = std::exchange(o.fd_, -1);
  }
  return *this;
}

OutputLock::~OutputLock() { release(); }

void OutputLock::release() {
  if (fd_ < 0) return;
  ::unlink(file_.c_str());  // while still held: nobody can take a lock on a file about to go
  ::close(fd_);
  fd_ = -1;
}

}  // namespace moreau::io
