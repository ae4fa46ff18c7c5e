// Each file app/cmd_*.cpp adds its subcommands to the `brdfnav` CLI through one function here.
#pragma once

#include <CLI/CLI.hpp>

#include <brdfnav/core/math.h>

#include <string>

namespace brdfnav::cli {

void add_eval_commands(CLI::App& app);  // eval, models
void add_demo_command(CLI::App& app);   // demo

// "x,y,z" -> normalised vector; throws std::runtime_error naming `option` when it is not three
// finite numbers or has zero length.
Vec3 parse_direction(const std::string& text, const std::string& option);

}  // namespace brdfnav::cli
