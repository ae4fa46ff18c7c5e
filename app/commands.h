// Each file app/cmd_*.cpp adds its subcommands to the `brdfnav` CLI through one function here.
#pragma once

#include <CLI/CLI.hpp>

#include <brdfnav/core/math.h>
#include <brdfnav/precompute/env_map.h>

#include <string>

namespace brdfnav {
class Scene;
}  // namespace brdfnav

namespace brdfnav::cli {

void add_eval_commands(CLI::App& app);        // eval, models
void add_demo_command(CLI::App& app);         // demo
void add_render_commands(CLI::App& app);      // render, distance
void add_precompute_commands(CLI::App& app);  // precompute, db-info
void add_navigate_commands(CLI::App& app);    // neighbors, variations, export
void add_bench_commands(CLI::App& app);       // bench render, bench navigator
void add_validate_command(CLI::App& app);     // validate
void add_serve_command(CLI::App& app);        // serve

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

// "x,y,z" -> normalised vector; throws Error(invalid_argument) naming `option` when it is not three
// finite numbers or has zero length.
Vec3 parse_direction(const std::string& text, const std::string& option);

// Fails before any work when `path` cannot become an output file: it names a directory, or its
// directory is missing or not writable. std::runtime_error naming `option` and the path.
void check_output_file(const std::string& path, const std::string& option);

EnvMap load_env(const RenderSetup& options);
Scene load_scene(const RenderSetup& options);

}  // namespace brdfnav::cli
