#include "progress.h"

#include <unistd.h>

#include <cstdio>
#include <memory>
#include <string>

namespace brdfnav::cli {

ProgressSink stderr_progress(const std::string& prefix) {
  const bool tty = ::isatty(STDERR_FILENO);
  struct Bar {
    std::string phase;  // the phase being drawn
    int last_decile = -1;
  };
  auto bar = std::make_shared<Bar>();
  return [=](std::string_view phase, std::size_t done, std::size_t total) {
    if (bar->phase != phase) *bar = Bar{std::string(phase)};
    const std::string what = prefix + bar->phase;
    const int percent = total > 0 ? int(100 * done / total) : 100;
    if (tty) {
      const int filled = percent * 30 / 100;
      std::fprintf(stderr, "\r%s [%.*s%*s] %3d%%%s", what.c_str(), filled,
                   "##############################", 30 - filled, "", percent,
                   done == total ? "\n" : "");
    } else if (percent / 10 != bar->last_decile) {
      bar->last_decile = percent / 10;
      std::fprintf(stderr, "%s: %d%%\n", what.c_str(), percent);
    }
  };
}

}  // namespace brdfnav::cli
