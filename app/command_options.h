// What several commands share: the options of a render and how they are loaded, the radius
// option's check, the check of an output file before any work. Each command itself is in its
// app/cmd_*.cpp (commands.h).
#pragma once

#include <CLI/CLI.hpp>

#include <brdfnav/precompute/env_map.h>

#include <string>

namespace brdfnav {
class Scene;
}  // namespace brdfnav

namespace brdfnav::cli {

// What a render is made from, the options every command that renders shares: the map (--env,
// --sanitize-env), the resolution (--res) and the scene (--scene).
struct RenderSetup {
  std::string env = kDefaultEnvPath;
  bool sanitize_env = false;
  int resolution = 320;
  std::string scene = "sphere";
};
void add_render_setup_options(CLI::App& cmd, RenderSetup& options);

// A navigation radius eps: a finite number of at least kMinRadius (brdfnav/navigator.h).
const CLI::Validator& radius_validator();

// Fails before any work when `path` cannot become an output file: it names a directory, or its
// directory is missing or not writable. Error(io) naming `option` and the path.
void check_output_file(const std::string& path, const std::string& option);

EnvMap load_env(const RenderSetup& options);
Scene load_scene(const RenderSetup& options);

}  // namespace brdfnav::cli
