#include "sphcore/output_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <sstream>
#include <utility>

#include "sphcore/case_file.hpp"

namespace sph {
namespace {

const char* kEndpointPrefix = "endpoint ";

// A descriptor that is closed when it goes out of scope, unless released.
class Descriptor {
 public:
  explicit Descriptor(int fd) : fd_(fd) {}
  ~Descriptor() {
    if (fd_ >= 0) ::close(fd_);
  }
  Descriptor(const Descriptor&) = delete;
  Descriptor& operator=(const Descriptor&) = delete;
  int get() const { return fd_; }
  int release() { return std::exchange(fd_, -1); }

 private:
  int fd_;
};

int open_lock_file(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0666);
  if (fd < 0)
    throw ConfigError(path + ": cannot open the output folder's lock: " + std::strerror(errno));
  return fd;
}

// Whether the launcher that started this process passed the lock of this
// very file (the same inode): then the folder is its run's. Trusted without
// a flock of its own, which on NFS (flock emulated by per-process record
// locks) would conflict with the launcher's.
bool inherited_from_launcher(const std::string& path) {
  const char* value = std::getenv(kOutputLockFdVariable);
  if (value == nullptr || *value == '\0') return false;
  char* end = nullptr;
  const long fd = std::strtol(value, &end, 10);
  if (*end != '\0' || fd < 0) return false;
  struct stat held = {};
  struct stat file = {};
  if (::fstat(static_cast<int>(fd), &held) != 0 || ::stat(path.c_str(), &file) != 0) return false;
  return held.st_dev == file.st_dev && held.st_ino == file.st_ino;
}

std::string read_all(int fd) {
  std::string text;
  char buffer[4096];
  for (off_t at = 0;;) {
    const ssize_t n = ::pread(fd, buffer, sizeof buffer, at);
    if (n <= 0) break;
    text.append(buffer, static_cast<std::size_t>(n));
    at += n;
  }
  return text;
}

// "pid N, started T: COMMAND" of the holder, and its endpoint (empty: a run
// of the launcher's or a solver alone, which share the folder with nobody).
struct Holder {
  std::string description, endpoint;
};

Holder holder_of(int fd) {
  std::istringstream lines(read_all(fd));
  Holder holder;
  std::getline(lines, holder.description);
  for (std::string line; std::getline(lines, line);)
    if (line.rfind(kEndpointPrefix, 0) == 0)
      holder.endpoint = line.substr(std::strlen(kEndpointPrefix));
  if (holder.description.empty()) holder.description = "a run that has not said which";
  return holder;
}

[[noreturn]] void refuse(const std::string& dir, const Holder& holder) {
  throw ConfigError(dir + " is in use by another run (" + holder.description +
                    "); wait for it to finish or choose another --out");
}

void write_holder(int fd, const std::string& path, const std::string& command,
                  const std::string& endpoint) {
  char started[32];
  const std::time_t now = std::time(nullptr);
  std::tm local{};
  localtime_r(&now, &local);
  std::strftime(started, sizeof started, "%Y-%m-%d %H:%M:%S", &local);
  std::string text =
      "pid " + std::to_string(::getpid()) + ", started " + started + ": " + command + "\n";
  if (!endpoint.empty()) text += kEndpointPrefix + endpoint + "\n";
  if (::ftruncate(fd, 0) != 0 ||
      ::pwrite(fd, text.data(), text.size(), 0) != static_cast<ssize_t>(text.size()))
    throw ConfigError(path + ": cannot write the output folder's lock: " + std::strerror(errno));
}

}  // namespace

void lock_output_dir(const std::string& dir, const std::string& endpoint,
                     const std::string& command) {
  const std::string path = dir + "/.cosph.lock";
  if (inherited_from_launcher(path)) return;
  // Joining is a check of the holder and a write of this process's name,
  // which must not interleave with another's: two processes of one run
  // started together would each find the other's lock not yet shared, or
  // its endpoint not yet written, and refuse. A second file serialises the
  // joins (held for the few system calls below); the launcher needs none,
  // as it never shares.
  Descriptor join(open_lock_file(path + ".join"));
  while (::flock(join.get(), LOCK_EX) != 0)
    if (errno != EINTR)
      throw ConfigError(path + ".join: cannot lock: " + std::string(std::strerror(errno)));
  Descriptor lock(open_lock_file(path));
  if (::flock(lock.get(), LOCK_EX | LOCK_NB) == 0) {
    // The first of its run: the folder is free.
    write_holder(lock.get(), path, command, endpoint);
    // Shared with the other processes of a coupled run; a launcher that took
    // the lock in the moment of the change is the run that holds the folder.
    if (!endpoint.empty() && ::flock(lock.get(), LOCK_SH | LOCK_NB) != 0)
      refuse(dir, holder_of(lock.get()));
    lock.release();  // held until the process exits
    return;
  }
  const Holder holder = holder_of(lock.get());
  if (endpoint.empty() || holder.endpoint != endpoint ||
      ::flock(lock.get(), LOCK_SH | LOCK_NB) != 0)
    refuse(dir, holder);
  lock.release();
}

std::string command_line(int argc, char** argv) {
  std::string line;
  for (int k = 0; k < argc; ++k) {
    const std::string argument = argv[k];
    if (k > 0) line += ' ';
    if (!argument.empty() && argument.find_first_of(" \t'\"") == std::string::npos) {
      line += argument;
      continue;
    }
    line += '\'';
    for (char c : argument) line += c == '\'' ? std::string("'\\''") : std::string(1, c);
    line += '\'';
  }
  return line;
}

}  // namespace sph
