#include "occlusion/io/file_bytes.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "occlusion/io/input_error.hpp"

namespace occlusion {
namespace {

// Closes the descriptor on every way out.
class Descriptor {
 public:
  explicit Descriptor(int fd) : fd_(fd) {}
  ~Descriptor() {
    if (fd_ >= 0) ::close(fd_);
  }
  Descriptor(const Descriptor&) = delete;
  Descriptor& operator=(const Descriptor&) = delete;
  int get() const { return fd_; }

 private:
  int fd_;
};

std::string kind_of(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISFIFO(mode)) return "a FIFO (named pipe)";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

}  // namespace

template <class Bytes>
Bytes read_file_bytes(const std::string& path) {
  // O_NONBLOCK: opening a FIFO for reading would otherwise wait for a writer.
  const Descriptor file(::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC));
  if (file.get() < 0) {
    throw InputError(path, 0, std::string("cannot open: ") + std::strerror(errno));
  }
  struct stat status {};
  if (::fstat(file.get(), &status) != 0) {
    throw InputError(path, 0, std::string("cannot stat: ") + std::strerror(errno));
  }
  if (!S_ISREG(status.st_mode)) {
    throw InputError(path, 0,
                     "is " + kind_of(status.st_mode) + ", not a regular file; give a file path");
  }
  const auto size = static_cast<std::uint64_t>(status.st_size);
  if (size > kMaxInputFileBytes) {
    throw InputError(path, 0,
                     "is " + std::to_string(size) + " bytes, more than the " +
                         std::to_string(kMaxInputFileBytes) + " bytes an input file may have");
  }
  Bytes bytes(static_cast<std::size_t>(size), '\0');
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t got = ::read(file.get(), bytes.data() + done, bytes.size() - done);
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) throw InputError(path, 0, std::string("read failed: ") + std::strerror(errno));
    if (got == 0) break;  // shrank while being read: what is there is the file
    done += static_cast<std::size_t>(got);
  }
  bytes.resize(done);
  return bytes;
}

template std::string read_file_bytes<std::string>(const std::string& path);
template LargeString read_file_bytes<LargeString>(const std::string& path);

}  // namespace occlusion
