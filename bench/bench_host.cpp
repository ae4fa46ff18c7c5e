// brdfnav_bench_host [--json FILE] HOST [RUNS]: what a host program costs as a whole process, the
// figures a renderer pays for loading brdfnav: the shared libraries `ldd HOST` lists, and over RUNS
// runs (default 50, after 3 unmeasured ones that warm the page cache) the median and 90th
// percentile wall time from spawn to exit and the largest peak resident set (wait4's ru_maxrss).
// The targets of a plugin a production renderer can load: at most 12 libraries, a median of at most
// 30 ms and a peak of at most 12 MB, for bench/host_one_closure.c. --json FILE also writes the
// figures for bench/results.py (which holds those targets for the table of bench/RESULTS.md).
#include "cli/bench_figures.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

extern char** environ;

namespace {

struct Run {
  double wall_ms;
  double peak_mib;
};

// One run of `host` with its output discarded.
Run run_once(const std::string& host) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  char* argv[] = {const_cast<char*>(host.c_str()), nullptr};
  const auto start = std::chrono::steady_clock::now();
  pid_t pid = 0;
  const int error = posix_spawn(&pid, host.c_str(), &actions, nullptr, argv, environ);
  posix_spawn_file_actions_destroy(&actions);
  if (error != 0)
    throw std::runtime_error(host + ": cannot start it (errno " + std::to_string(error) + ")");
  int status = 0;
  rusage usage{};
  if (wait4(pid, &status, 0, &usage) != pid) throw std::runtime_error(host + ": wait4 failed");
  const auto end = std::chrono::steady_clock::now();
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw std::runtime_error(host + ": did not exit with status 0");
  return {std::chrono::duration<double, std::milli>(end - start).count(),
          static_cast<double>(usage.ru_maxrss) / 1024.0};
}

int count_libraries(const std::string& host) {
  FILE* ldd = popen(("ldd '" + host + "'").c_str(), "r");
  if (!ldd) throw std::runtime_error("cannot run ldd");
  int lines = 0;
  for (int c; (c = std::fgetc(ldd)) != EOF;) lines += c == '\n';
  if (pclose(ldd) != 0) throw std::runtime_error("ldd " + host + " failed");
  return lines;
}

double percentile(std::vector<double> v, double p) {
  std::sort(v.begin(), v.end());
  return v[static_cast<std::size_t>(p * double(v.size() - 1) + 0.5)];
}

const char* verdict(bool met) {
  return met ? "met" : "NOT met";
}

}  // namespace

int main(int argc, char** argv) {
  std::string json;
  if (argc > 2 && std::string(argv[1]) == "--json") {
    json = argv[2];
    argv += 2, argc -= 2;
  }
  if (argc < 2 || argc > 3) {
    std::fprintf(stderr, "usage: brdfnav_bench_host [--json FILE] HOST [RUNS]\n");
    return 2;
  }
  const std::string host = argv[1];
  const int runs = argc == 3 ? std::atoi(argv[2]) : 50;
  if (runs < 5) {
    std::fprintf(stderr, "%s: RUNS must be at least 5\n", argv[0]);
    return 2;
  }
  try {
    const int libraries = count_libraries(host);
    for (int i = 0; i < 3; ++i) run_once(host);
    std::vector<double> wall, peak;
    for (int i = 0; i < runs; ++i) {
      const Run r = run_once(host);
      wall.push_back(r.wall_ms);
      peak.push_back(r.peak_mib);
    }
    const double median = percentile(wall, 0.5), p90 = percentile(wall, 0.9);
    const double max_peak = *std::max_element(peak.begin(), peak.end());
    std::printf("host: %s (%d runs)\n", host.c_str(), runs);
    std::printf("| figure | value | target |\n|---|---:|---|\n");
    std::printf("| shared libraries (ldd) | %d | <= 12: %s |\n", libraries,
                verdict(libraries <= 12));
    std::printf("| wall time, median | %.2f ms | <= 30 ms: %s |\n", median, verdict(median <= 30));
    std::printf("| wall time, 90th percentile | %.2f ms | - |\n", p90);
    std::printf("| peak RSS, largest | %.2f MiB | <= 12 MB: %s |\n", max_peak,
                verdict(max_peak * 1.048576 <= 12));
    brdfnav::cli::BenchFigures figures("host");
    figures.add("libraries", libraries);
    figures.add("wall_median_ms", median);
    figures.add("wall_p90_ms", p90);
    figures.add("peak_rss_mib", max_peak);
    figures.write(json);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "brdfnav_bench_host: %s\n", e.what());
    return 1;
  }
  return 0;
}
