#include "progress.h"

#include <unistd.h>

#include <cstdio>
#include <memory>

namespace brdfnav::cli {

ProgressSink stderr_progress(const std::string& what) {
  const bool tty = ::isatty(STDERR_FILENO);
  auto last_decile = std::make_shared<int>(-1);
  return [=](int done, int total) {
    const int percent = total > 0 ? 100 * done / total : 100;
    if (tty) {
      const int filled = percent * 30 / 100;
      std::fprintf(stderr, "\r%s [%.*s%*s] %3d%%%s", what.c_str(), filled,
                   "##############################", 30 - filled, "", percent,
                   done == total ? "\n" : "");
    } else if (percent / 10 != *last_decile) {
      *last_decile = percent / 10;
      std::fprintf(stderr, "%s: %d%%\n", what.c_str(), percent);
    }
  };
}

}  // namespace brdfnav::cli
