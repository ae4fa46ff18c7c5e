// Each file app/cmd_*.cpp adds its subcommands to the `brdfnav` CLI through one function here.
#pragma once

#include <CLI/CLI.hpp>

namespace brdfnav::cli {

void add_eval_commands(CLI::App& app);        // eval, models
void add_demo_command(CLI::App& app);         // demo
void add_render_commands(CLI::App& app);      // render, distance
void add_precompute_commands(CLI::App& app);  // precompute, db-info
void add_navigate_commands(CLI::App& app);    // neighbors, variations, export
void add_bench_commands(CLI::App& app);       // bench render, bench navigator
void add_validate_command(CLI::App& app);     // validate
void add_serve_command(CLI::App& app);        // serve

}  // namespace brdfnav::cli
