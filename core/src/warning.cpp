#include <brdfnav/core/warning.h>

#include <cstdio>

namespace brdfnav {

void warn_to_stderr(const std::string& line) {
  std::fprintf(stderr, "brdfnav: warning: %s\n", line.c_str());
}

}  // namespace brdfnav
