#include "rigid_body_sim/ros/regular_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "rigid_body_sim/ros/scene_error.h"

namespace rigid_body_sim {
namespace {

// Closes the descriptor on every way out.
class FileDescriptor {
 public:
  explicit FileDescriptor(int fd) : fd_(fd) {}
  ~FileDescriptor() {
    if (fd_ >= 0) ::close(fd_);
  }
  FileDescriptor(const FileDescriptor&) = delete;
  FileDescriptor& operator=(const FileDescriptor&) = delete;
  int get() const { return fd_; }

 private:
  int fd_;
};

std::string KindOf(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISFIFO(mode)) return "a FIFO";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  return "of an unknown type";
}

std::string TooLong(const std::string& what, std::size_t max_bytes) {
  return what + " is more than the limit of " + std::to_string(max_bytes) + " bytes";
}

}  // namespace

std::string ReadRegularFile(const std::string& path, std::size_t max_bytes, const std::string& what,
                            LastLink last_link) {
  // O_NONBLOCK: opening a FIFO or a device returns at once; O_NOCTTY: a
  // terminal named here never becomes the node's.
  int flags = O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC;
  if (last_link == LastLink::kRefuse) flags |= O_NOFOLLOW;
  const FileDescriptor file(::open(path.c_str(), flags));
  if (file.get() < 0) throw SceneError(what + " cannot be read: " + std::strerror(errno));
  struct stat status {};
  if (::fstat(file.get(), &status) != 0) {
    throw SceneError(what + " cannot be read: " + std::strerror(errno));
  }
  if (!S_ISREG(status.st_mode)) {
    throw SceneError(what + " is not a regular file (it is " + KindOf(status.st_mode) + ")");
  }
  if (static_cast<std::size_t>(status.st_size) > max_bytes)
    throw SceneError(TooLong(what, max_bytes));
  // Read to the end, not to st_size: a file that grew past the limit since
  // fstat is refused one chunk past it.
  std::string text;
  text.reserve(static_cast<std::size_t>(status.st_size));
  char chunk[65536];
  while (text.size() <= max_bytes) {
    const ssize_t got = ::read(file.get(), chunk, sizeof(chunk));
    if (got == 0) break;
    if (got < 0) {
      if (errno == EINTR) continue;
      throw SceneError(what + " cannot be read: " + std::strerror(errno));
    }
    text.append(chunk, static_cast<std::size_t>(got));
  }
  if (text.size() > max_bytes) throw SceneError(TooLong(what, max_bytes));
  return text;
}

}  // namespace rigid_body_sim
