// Runs the brdfnav CLI as a user would and captures its exit code, stdout and stderr.
#pragma once

#include <sys/wait.h>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace brdfnav::test {

struct CliResult {
  int exit_code;
  std::string out, err;
};

inline std::string read_text(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// `args` is appended to the binary path as shell words (quote them yourself when needed).
inline CliResult run_cli(const std::string& args) {
  static int counter = 0;
  const auto err_path =
      std::filesystem::temp_directory_path() /
      ("brdfnav_cli_err_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
  const std::string cmd = std::string(BRDFNAV_CLI) + " " + args + " 2>" + err_path.string();
  CliResult r{-1, {}, {}};
  if (FILE* pipe = ::popen(cmd.c_str(), "r")) {
    std::array<char, 4096> buf;
    std::size_t n;
    while ((n = std::fread(buf.data(), 1, buf.size(), pipe)) > 0) r.out.append(buf.data(), n);
    const int status = ::pclose(pipe);
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  }
  r.err = read_text(err_path);
  std::filesystem::remove(err_path);
  return r;
}

// The database the CLI suites query: CTest's shared test-profile database (BRDFNAV_TEST_DATABASE),
// or, run alone, one the CLI builds under `root`. Empty when that build fails (its error is in
// `error`).
inline std::filesystem::path suite_database(const std::filesystem::path& root, std::string& error) {
  if (const char* shared = std::getenv("BRDFNAV_TEST_DATABASE"); shared && *shared) return shared;
  const std::filesystem::path db = root / "db";
  const CliResult r = run_cli("precompute --profile test --out " + db.string());
  if (r.exit_code != 0) {
    error = r.err;
    return {};
  }
  return db;
}

}  // namespace brdfnav::test
