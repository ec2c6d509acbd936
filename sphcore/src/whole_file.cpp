#include "sphcore/whole_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>

namespace sph {

std::string system_reason(int error_number) {
  return error_number != 0 ? std::strerror(error_number) : "unknown reason";
}

namespace {

// Writes all of `text` to `fd`; the errno of the first failure, or 0.
int write_all(int fd, const std::string& text) {
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return n < 0 ? errno : ENOSPC;
    done += static_cast<std::size_t>(n);
  }
  return 0;
}

}  // namespace

void write_whole_file(const std::string& path, const std::string& text, Sync sync) {
  const std::string partial = path + ".partial";
  const int fd = ::open(partial.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) throw std::runtime_error(partial + ": cannot create it: " + system_reason(errno));
  int failure = write_all(fd, text);
  if (failure == 0 && sync == Sync::to_disk && ::fsync(fd) != 0) failure = errno;
  if (::close(fd) != 0 && failure == 0) failure = errno;
  if (failure == 0 && std::rename(partial.c_str(), path.c_str()) != 0) failure = errno;
  if (failure != 0) {
    std::remove(partial.c_str());
    throw std::runtime_error(path + ": cannot write it (" + system_reason(failure) +
                             "); the previous version, if any, is kept");
  }
}

}  // namespace sph
