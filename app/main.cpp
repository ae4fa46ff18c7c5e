// brdfnav: the command-line front end. Every failure prints one line naming what is wrong and
// exits non-zero; commands that write files write them atomically.
#include "commands.h"

#include <cstdio>
#include <exception>

int main(int argc, char** argv) {
  CLI::App app{"brdfnav: image-driven navigation of analytic BRDF models", "brdfnav"};
  app.require_subcommand(1);
  app.set_help_all_flag("--help-all", "Help for every command");
  brdfnav::cli::add_eval_commands(app);
  brdfnav::cli::add_demo_command(app);
  brdfnav::cli::add_render_commands(app);
  brdfnav::cli::add_precompute_commands(app);
  brdfnav::cli::add_navigate_commands(app);
  brdfnav::cli::add_bench_commands(app);
  brdfnav::cli::add_validate_command(app);
  brdfnav::cli::add_serve_command(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "brdfnav: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
