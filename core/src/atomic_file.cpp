#include <brdfnav/core/atomic_file.h>

#include <brdfnav/core/error.h>

#include <fcntl.h>
#include <unistd.h>
#include <atomic>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace brdfnav {

namespace {
std::filesystem::path temp_beside(const std::filesystem::path& target) {
  static std::atomic<unsigned> counter{0};
  std::string name = ".";
  name += target.stem().string();
  name += ".tmp" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
  name += target.extension().string();
  return target.parent_path() / name;
}
}  // namespace

AtomicOutput::AtomicOutput(std::filesystem::path target)
    : target_(std::move(target)), temp_(temp_beside(target_)) {}

AtomicOutput::~AtomicOutput() {
  if (committed_) return;
  std::error_code ignored;
  std::filesystem::remove(temp_, ignored);
}

void AtomicOutput::commit() {
  std::error_code ec;
  std::filesystem::rename(temp_, target_, ec);
  if (ec) throw Error(ErrorCode::io, target_.string(), "cannot write: " + ec.message());
  committed_ = true;
}

namespace {

[[noreturn]] void fail(const std::filesystem::path& target, const std::string& why) {
  throw Error(ErrorCode::io, target.string(), "cannot write: " + why);
}

void write_all(int fd, std::string_view contents, const std::filesystem::path& target) {
  while (!contents.empty()) {
    const ssize_t n = ::write(fd, contents.data(), contents.size());
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) fail(target, std::strerror(errno));
    contents.remove_prefix(static_cast<std::size_t>(n));
  }
  // On disk before it gets its name: a power cut after the rename finds the new contents.
  if (::fsync(fd) != 0) fail(target, std::strerror(errno));
}

// The file descriptor closes on every path out.
struct Fd {
  int fd;
  ~Fd() {
    if (fd >= 0) ::close(fd);
  }
};

std::filesystem::path directory_of(const std::filesystem::path& target) {
  return target.has_parent_path() ? target.parent_path() : std::filesystem::path(".");
}

// An unnamed file in the target's directory (Linux's O_TMPFILE), or -1 where the filesystem
// has none; throws when the directory cannot take a file at all.
int open_unnamed(const std::filesystem::path& target) {
  const int fd = ::open(directory_of(target).c_str(), O_TMPFILE | O_WRONLY | O_CLOEXEC, 0666);
  if (fd < 0 && errno != EOPNOTSUPP && errno != EISDIR && errno != EINVAL)
    fail(target, std::strerror(errno));
  return fd;
}

}  // namespace

// The contents go to an unnamed file that gets a (hidden) name only once it is complete and on
// disk, then the target's name by rename: a kill before the link leaves nothing behind, one
// between link and rename a complete hidden temporary. Where O_TMPFILE is missing, a named
// temporary takes the unnamed file's place.
void write_file_atomic(const std::filesystem::path& target, std::string_view contents) {
  AtomicOutput out(target);
  Fd file{open_unnamed(target)};
  if (file.fd >= 0) {
    write_all(file.fd, contents, target);
    const std::string self = "/proc/self/fd/" + std::to_string(file.fd);
    if (::linkat(AT_FDCWD, self.c_str(), AT_FDCWD, out.temp_path().c_str(), AT_SYMLINK_FOLLOW))
      fail(target, std::strerror(errno));
  } else {
    file.fd = ::open(out.temp_path().c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (file.fd < 0) fail(target, std::strerror(errno));
    write_all(file.fd, contents, target);
  }
  out.commit();
  // The rename itself on disk.
  Fd dir{::open(directory_of(target).c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC)};
  if (dir.fd >= 0) ::fsync(dir.fd);
}

std::string read_file(const std::filesystem::path& path) {
  const std::string name = path.string();
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw Error(ErrorCode::io, name, "is a directory");
  std::ifstream file(path, std::ios::binary);
  if (!file) throw Error(ErrorCode::io, name, std::string("cannot open: ") + std::strerror(errno));
  std::ostringstream text;
  text << file.rdbuf();
  if (file.bad()) throw Error(ErrorCode::io, name, "cannot read");
  return text.str();
}

}  // namespace brdfnav
