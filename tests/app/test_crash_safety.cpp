// Crash safety (docs/RELIABILITY.md): `brdfnav precompute` killed with SIGKILL anywhere in its run,
// then run again with --resume, gives a database byte for byte the one an uninterrupted run gives;
// a killed `brdfnav export` leaves its output either absent or complete. Every run is of the same
// binary in this process, so that a change of the renderer between builds cannot make them differ.
#include "app/cli_runner.h"

#include <gtest/gtest.h>

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <functional>
#include <map>
#include <vector>

namespace brdfnav::test {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

// Where to kill a run: after `delay` seconds or, when `trigger` is set, as soon as a line of its
// stderr starts with it (the progress lines name the phase, which a delay would rarely hit when
// the phase is short).
struct KillPoint {
  double delay = 0;
  std::string trigger;
};

// Starts BRDFNAV_CLI with `args`, stdout to /dev/null and stderr to a pipe it returns.
pid_t spawn(const std::vector<std::string>& args, int& stderr_fd) {
  int fds[2];
  if (::pipe(fds) != 0) return -1;
  const pid_t pid = ::fork();
  if (pid == 0) {
    std::vector<char*> argv{const_cast<char*>(BRDFNAV_CLI)};
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    const int null = ::open("/dev/null", O_WRONLY);
    ::dup2(null, STDOUT_FILENO);
    ::dup2(fds[1], STDERR_FILENO);
    ::close(fds[0]);
    ::execv(BRDFNAV_CLI, argv.data());
    ::_exit(127);
  }
  ::close(fds[1]);
  stderr_fd = fds[0];
  return pid;
}

// Runs the CLI and kills it at `k`. Returns the last line it printed before the kill (where it
// was), or "finished" when it ended first.
std::string run_and_kill(const std::vector<std::string>& args, const KillPoint& k) {
  int fd = -1;
  const pid_t pid = spawn(args, fd);
  const auto deadline =
      Clock::now() + std::chrono::duration<double>(k.trigger.empty() ? k.delay : 120);
  std::string pending, last = "started";
  bool killed = false;
  while (!killed) {
    const double left = std::chrono::duration<double, std::milli>(deadline - Clock::now()).count();
    pollfd p{fd, POLLIN, 0};
    if (left <= 0 || ::poll(&p, 1, int(left) + 1) == 0) {
      killed = true;
      break;
    }
    char buf[4096];
    const ssize_t n = ::read(fd, buf, sizeof buf);
    if (n <= 0) break;  // it exited
    pending.append(buf, std::size_t(n));
    for (std::size_t eol; (eol = pending.find('\n')) != std::string::npos;) {
      last = pending.substr(0, eol);
      pending.erase(0, eol + 1);
      if (!k.trigger.empty() && last.rfind(k.trigger, 0) == 0) killed = true;
    }
  }
  if (killed) ::kill(pid, SIGKILL);
  ::close(fd);
  int status = 0;
  ::waitpid(pid, &status, 0);
  return WIFSIGNALED(status) ? last : "finished";
}

// Every file under `dir` (relative path -> contents).
std::map<std::string, std::string> files_of(const fs::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file())
      files[fs::relative(e.path(), dir).generic_string()] = read_text(e.path());
  return files;
}

// Deterministic fractions in (0, 1): a fixed linear congruential sequence, so that every run of
// the test kills at the same delays.
std::vector<double> fractions(int count, std::uint64_t seed) {
  std::vector<double> out;
  for (int i = 0; i < count; ++i) {
    seed = seed * 6364136223846793005ull + 1442695040888963407ull;
    out.push_back(0.05 + 0.95 * double(seed >> 11) / double(1ull << 53));
  }
  return out;
}

double seconds_of(const std::function<void()>& f) {
  const auto start = Clock::now();
  f();
  return std::chrono::duration<double>(Clock::now() - start).count();
}

class CrashSafety : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = fs::temp_directory_path() / ("brdfnav_crash_" + std::to_string(::getpid()));
    fs::remove_all(root_);
    fs::create_directories(root_);
  }
  void TearDown() override { fs::remove_all(root_); }
  // The smallest build that has every phase: the smoke profile at 8 x 8.
  static std::vector<std::string> precompute(const fs::path& out) {
    return {"precompute", "--profile", "smoke", "--res", "8", "--out", out.string()};
  }
  fs::path root_;
};

TEST_F(CrashSafety, KilledPrecomputeResumesToTheSameBytes) {
  const fs::path reference = root_ / "reference";
  CliResult full;
  const double seconds = seconds_of(
      [&] { full = run_cli("precompute --profile smoke --res 8 --out " + reference.string()); });
  ASSERT_EQ(full.exit_code, 0) << full.err;
  const std::map<std::string, std::string> expected = files_of(reference);

  // Kills spread over the whole run by delay, then one in each phase after the render by its
  // progress lines; the last trial is killed twice, the second time while it resumes.
  std::vector<std::vector<KillPoint>> trials;
  for (double f : fractions(5, 8)) trials.push_back({{f * seconds, {}}});
  for (const char* phase : {"load images: 50%", "embedding: 0%", "fits: 50%", "checksums: 50%"})
    trials.push_back({{0, phase}});
  trials.push_back({{0.5 * seconds, {}}, {0, "fits: 20%"}});

  for (std::size_t t = 0; t < trials.size(); ++t) {
    const fs::path out = root_ / ("trial" + std::to_string(t));
    std::vector<std::string> args = precompute(out);
    for (const KillPoint& k : trials[t]) {
      const std::string where = run_and_kill(args, k);
      std::printf("trial %zu: killed at %.2f s / '%s': last line '%s'\n", t, k.delay,
                  k.trigger.c_str(), where.c_str());
      args = precompute(out);
      args.push_back("--resume");
    }
    if (!fs::exists(out)) {  // a kill after the final rename leaves the finished database
      std::string line;
      for (const std::string& a : args) line += a + " ";
      const CliResult resumed = run_cli(line);
      ASSERT_EQ(resumed.exit_code, 0) << "trial " << t << ": " << resumed.err;
    }
    EXPECT_FALSE(fs::exists(out.string() + ".partial")) << "trial " << t;
    EXPECT_TRUE(files_of(out) == expected) << "trial " << t << ": " << out << " differs";
  }
}

TEST_F(CrashSafety, KilledExportLeavesNoPartialFile) {
  const fs::path db = root_ / "db";
  const CliResult built = run_cli("precompute --profile smoke --res 8 --out " + db.string());
  ASSERT_EQ(built.exit_code, 0) << built.err;
  const fs::path out = root_ / "exports" / "chosen.yaml";
  fs::create_directories(out.parent_path());
  const std::vector<std::string> args{"export",       "--db",  db.string(), "--material",
                                      "he:sigma=0.3", "--out", out.string()};
  double seconds = 0;
  CliResult full;
  seconds = seconds_of([&] {
    full = run_cli("export --db " + db.string() + " --material he:sigma=0.3 --out " + out.string());
  });
  ASSERT_EQ(full.exit_code, 0) << full.err;
  const std::string expected = read_text(out);

  int absent = 0, complete = 0;
  for (double f : fractions(30, 9)) {
    fs::remove(out);
    run_and_kill(args, {1.2 * f * seconds, {}});
    if (!fs::exists(out)) {
      ++absent;
      continue;
    }
    EXPECT_EQ(read_text(out), expected) << "killed at " << 1.2 * f * seconds << " s";
    ++complete;
  }
  // A kill between the temporary's creation and its rename leaves the temporary (a hidden
  // ".chosen.tmp<pid>-<n>.yaml" beside the output): litter, never the output.
  const auto entries = std::distance(fs::directory_iterator(out.parent_path()), {});
  std::printf("export: %d kills, %d left no file, %d a complete one; %d temporaries left\n",
              absent + complete, absent, complete, int(entries) - (fs::exists(out) ? 1 : 0));
}

}  // namespace
}  // namespace brdfnav::test
