#include <brdfnav/core/atomic_file.h>

#include <unistd.h>
#include <atomic>
#include <cstdio>
#include <fstream>
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
  if (ec) throw std::runtime_error(target_.string() + ": cannot write: " + ec.message());
  committed_ = true;
}

void write_file_atomic(const std::filesystem::path& target, std::string_view contents) {
  AtomicOutput out(target);
  {
    std::ofstream file(out.temp_path(), std::ios::binary);
    file.write(contents.data(), static_cast<std::streamsize>(contents.size()));
    file.flush();
    if (!file) throw std::runtime_error(target.string() + ": cannot write");
  }
  out.commit();
}

}  // namespace brdfnav
