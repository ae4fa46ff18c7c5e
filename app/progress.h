// Progress reporting on stderr, shared by the commands that run long phases.
#pragma once

#include <brdfnav/core/progress.h>

#include <string>

namespace brdfnav::cli {

// One bar per phase, labelled `prefix` then the phase's name: redrawn on a terminal, a plain
// line every 10% otherwise.
ProgressSink stderr_progress(const std::string& prefix);

}  // namespace brdfnav::cli
