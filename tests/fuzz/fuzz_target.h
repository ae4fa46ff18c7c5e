// What the fuzz targets of tests/fuzz share. Each target file defines libFuzzer's entry point,
// LLVMFuzzerTestOneInput: `./run fuzz` links it with -fsanitize=fuzzer (clang), and the normal
// build links it with corpus_replay.cpp, which feeds it every file of tests/corpus/<target>/
// (in the fuzzing tree the libFuzzer executable replays those files).
//
// A target catches the errors its function documents (the expected outcome of bad input) and
// nothing else: any other exception escapes, ends in std::terminate under libFuzzer (which saves
// the input as a crash) and fails the replay test naming the file, as a crash or a sanitizer
// report does.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <string_view>

#include <unistd.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace brdfnav::fuzz {

inline std::string_view as_text(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

// A property the input broke (not an exception, so that nothing on the way can swallow it).
[[noreturn]] inline void fail(const std::string& what) {
  std::fprintf(stderr, "brdfnav fuzz: %s\n", what.c_str());
  std::abort();
}

inline std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

inline void write_file(const std::filesystem::path& path, std::string_view bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (!out) fail("cannot write " + path.string());
}

// A directory of this process under the temporary directory, removed at a normal exit (after a
// crash it stays, with the files of the input that crashed).
inline const std::filesystem::path& scratch_dir() {
  struct Dir {
    std::filesystem::path path =
        std::filesystem::temp_directory_path() / ("brdfnav_fuzz_" + std::to_string(::getpid()));
    Dir() { std::filesystem::create_directories(path); }
    ~Dir() { std::filesystem::remove_all(path); }
  };
  static const Dir dir;
  return dir.path;
}

}  // namespace brdfnav::fuzz
