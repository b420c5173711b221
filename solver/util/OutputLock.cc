#include <solver/util/OutputLock.hpp>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>

#include <solver/util/InputError.hpp>

namespace beamimpact {
namespace {

/// The pid the holder wrote into the lock file ("unknown" while it is still writing it).
std::string holder_pid(int fd) {
  char text[32] = {};
  const ssize_t n = pread(fd, text, sizeof text - 1, 0);
  std::string pid = n > 0 ? std::string(text, static_cast<std::size_t>(n)) : std::string();
  while (!pid.empty() && (pid.back() == '\n' || pid.back() == ' ')) pid.pop_back();
  return pid.empty() ? "unknown" : pid;
}

}  // namespace

OutputLock::OutputLock(const std::filesystem::path& dir) {
  if (dir.empty()) return;
  std::error_code ec;  // a file, a read-only parent, a name too long: bad input, said once here
  if (std::filesystem::create_directories(dir, ec); ec)
    throw InputError(dir.string(), "--out", "expected a directory that can be written: " + ec.message());
  const std::filesystem::path f = file(dir);
  // O_CLOEXEC: the lock belongs to this process alone, not to the programs it starts.
  fd_ = open(f.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0)
    throw InputError(dir.string(), "--out",
                     "cannot open the directory's lock " + f.string() + ": " + std::strerror(errno));
  if (flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    const int err = errno;
    const std::string pid = holder_pid(fd_);
    close(fd_);
    fd_ = -1;
    if (err == EWOULDBLOCK)
      throw InputError(dir.string(), "--out",
                       "another command is writing into this directory (pid " + pid + ", lock " + f.string() +
                           "); wait for it to end or choose another directory");
    throw InputError(dir.string(), "--out", "cannot lock " + f.string() + ": " + std::strerror(err));
  }
  // The holder's pid, for the message a second writer gets; the lock holds without it.
  const std::string pid = std::to_string(getpid()) + "\n";
  const bool named =
      ftruncate(fd_, 0) == 0 && pwrite(fd_, pid.data(), pid.size(), 0) == static_cast<ssize_t>(pid.size());
  (void)named;
}

OutputLock::~OutputLock() {
  if (fd_ >= 0) close(fd_);  // releases the lock
}

}  // namespace beamimpact
