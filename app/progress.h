// Progress reporting on stderr, shared by the commands that run long phases.
#pragma once

#include <brdfnav/renderer/render.h>

#include <string>

namespace brdfnav::cli {

// A redrawn bar on a terminal, a plain line every 10% otherwise.
ProgressSink stderr_progress(const std::string& what);

}  // namespace brdfnav::cli
