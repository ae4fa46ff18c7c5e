// Writing outputs so that nothing is ever half-written: write a temporary file beside the target,
// then rename it over the target. A failure or a crash leaves the old file (or no file). And
// reading inputs whole, with an error that names the file.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace brdfnav {

// A temporary path beside `target`; commit() renames it onto the target, and the destructor
// removes the temporary if commit() was never reached. For writers that take a path (OIIO).
class AtomicOutput {
 public:
  explicit AtomicOutput(std::filesystem::path target);
  ~AtomicOutput();
  AtomicOutput(const AtomicOutput&) = delete;
  AtomicOutput& operator=(const AtomicOutput&) = delete;

  // Where to write. Keeps the target's extension, so format detection by name still works.
  const std::filesystem::path& temp_path() const { return temp_; }
  const std::filesystem::path& target() const { return target_; }
  // Renames the temporary onto the target; throws Error (ErrorCode::io, brdfnav/core/error.h)
  // naming the target.
  void commit();

 private:
  std::filesystem::path target_, temp_;
  bool committed_ = false;
};

// Writes `contents` to `target` atomically and durably: an unnamed temporary (O_TMPFILE, where
// the filesystem has it) flushed to disk before it is renamed onto the target, so that a killed
// writer leaves no file behind. Throws Error (ErrorCode::io) naming the target.
void write_file_atomic(const std::filesystem::path& target, std::string_view contents);

// The whole of an input file. Throws Error (ErrorCode::io) naming the file when it is a directory
// or cannot be opened or read (the system's reason).
std::string read_file(const std::filesystem::path& path);

}  // namespace brdfnav
