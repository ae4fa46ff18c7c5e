// Warnings: what a layer reports and goes on (a map's texels clamped, a config that is not
// colour-managed). Each takes a sink, so that a caller may collect, show or silence them.
#pragma once

#include <functional>
#include <string>

namespace brdfnav {

// Receives one line per warning (no trailing newline).
using WarningSink = std::function<void(const std::string&)>;

// The default sink: "brdfnav: warning: LINE" on stderr.
void warn_to_stderr(const std::string& line);

}  // namespace brdfnav
