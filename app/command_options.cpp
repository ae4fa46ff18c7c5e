#include "command_options.h"

#include <brdfnav/core/atomic_file.h>
#include <brdfnav/core/error.h>
#include <brdfnav/navigator/navigator.h>

#include <filesystem>
#include <fstream>

namespace brdfnav::cli {

void add_render_setup_options(CLI::App& cmd, RenderSetup& o) {
  cmd.add_option("--env", o.env, "Lat-long HDR environment map (any format OpenImageIO reads)")
      ->capture_default_str();
  cmd.add_flag("--sanitize-env", o.sanitize_env, "Replace NaN/Inf texels by 0 instead of failing");
  cmd.add_option("--res", o.resolution, "Image width and height in pixels")
      ->capture_default_str()
      ->check(CLI::Range(8, 4096));
  cmd.add_option("--scene", o.scene, "'sphere' or a triangle mesh (OBJ)")->capture_default_str();
}

void check_output_file(const std::string& path, const std::string& option) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw Error(ErrorCode::io, option + " " + path, "is a directory");
  const AtomicOutput probe(path);  // removes its temporary file
  if (!std::ofstream(probe.temp_path()))
    throw Error(ErrorCode::io, option + " " + path, "cannot create a file in its directory");
}

// CLI11's PositiveNumber lets NaN through (NaN <= 0 is false). Checked here as well as by the
// navigator so that the error names the option, before the database is opened.
const CLI::Validator& radius_validator() {
  static const CLI::Validator validator(
      [](std::string& text) -> std::string {
        try {
          std::size_t used = 0;
          const double value = std::stod(text, &used);
          if (used == text.size() && valid_radius(value)) return "";
        } catch (const std::exception&) {
        }
        return radius_requirement() + ", got '" + text + "'";
      },
      "RADIUS");
  return validator;
}

}  // namespace brdfnav::cli
