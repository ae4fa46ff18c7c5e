// What several commands share: the render options (into a RenderSetup), the radius option's
// check, the check of an output file before any work. Each command itself is in its
// app/cmd_*.cpp (commands.h).
#pragma once

#include <CLI/CLI.hpp>

#include <brdfnav/renderer/render_setup.h>

#include <string>

namespace brdfnav::cli {

// The options every command that renders shares, into a RenderSetup: the map (--env,
// --sanitize-env), the resolution (--res) and the scene (--scene).
void add_render_setup_options(CLI::App& cmd, RenderSetup& options);

// A navigation radius eps: a finite number of at least kMinRadius (brdfnav/navigator.h).
const CLI::Validator& radius_validator();

// Fails before any work when `path` cannot become an output file: it names a directory, or its
// directory is missing or not writable. Error(io) naming `option` and the path.
void check_output_file(const std::string& path, const std::string& option);

}  // namespace brdfnav::cli
