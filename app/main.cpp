// brdfnav: the command-line front end. Every failure prints one line "brdfnav: error: ..." naming
// what is wrong and exits with the status of its kind (exit_status(), listed by the help's footer):
// 2 a wrong command line or argument, 3 a malformed material, spec or profile, 4 a file that
// cannot be read or written, 5 a damaged or mismatched database, 1 an internal failure. Commands
// that write files write them atomically.
#include "commands.h"

#include <brdfnav/core/error.h>

#include <algorithm>
#include <cstdio>
#include <exception>
#include <string>
#include <string_view>
#include <vector>

namespace {

// Edit distance between two command names, for a suggestion.
std::size_t distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] != b[j - 1])});
      diagonal = up;
    }
  }
  return row[b.size()];
}

// "unknown command 'X'" with the nearest command and the list, when the first argument names no
// command; empty when it does (or is an option).
std::string unknown_command(const CLI::App& app, int argc, char** argv) {
  if (argc < 2 || argv[1][0] == '-') return "";
  const std::string given = argv[1];
  std::string names, nearest;
  std::size_t best = 3;  // suggest within two edits
  for (const CLI::App* sub : app.get_subcommands({})) {
    if (sub->get_name() == given) return "";
    names += (names.empty() ? "" : ", ") + sub->get_name();
    if (const std::size_t d = distance(given, sub->get_name()); d < best)
      best = d, nearest = sub->get_name();
  }
  return "unknown command '" + given + "'" +
         (nearest.empty() ? "" : " (did you mean '" + nearest + "'?)") + "; commands: " + names;
}

int usage_error(const std::string& message) {
  std::fprintf(stderr, "brdfnav: error: %s\nRun 'brdfnav --help' or 'brdfnav COMMAND --help'.\n",
               message.c_str());
  return 2;
}

// The exit status of a failure, by its kind; the help's footer lists them (kExitStatuses).
int exit_status(brdfnav::ErrorCode code) {
  using brdfnav::ErrorCode;
  switch (code) {
    case ErrorCode::invalid_argument:
      return 2;  // as a command line that does not parse
    case ErrorCode::parse:
      return 3;
    case ErrorCode::io:
      return 4;
    case ErrorCode::database:
      return 5;
    case ErrorCode::internal:
      return 1;
  }
  return 1;
}

constexpr const char* kExitStatuses =
    "Exit status: 0 done; 1 an internal failure; 2 a wrong command line or argument; 3 a "
    "malformed material, spec or profile; 4 a file that cannot be read or written; 5 a database "
    "that is missing, corrupt or not the one its files name.";

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"brdfnav: image-driven navigation of analytic BRDF models", "brdfnav"};
  app.require_subcommand(1);
  app.set_help_all_flag("--help-all", "Help for every command");
  app.footer(kExitStatuses);
  brdfnav::cli::add_eval_commands(app);
  brdfnav::cli::add_demo_command(app);
  brdfnav::cli::add_render_commands(app);
  brdfnav::cli::add_precompute_commands(app);
  brdfnav::cli::add_navigate_commands(app);
  brdfnav::cli::add_bench_commands(app);
  brdfnav::cli::add_validate_command(app);
  brdfnav::cli::add_serve_command(app);
  if (const std::string unknown = unknown_command(app, argc, argv); !unknown.empty())
    return usage_error(unknown);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help, --help-all
    if (argc < 2) return usage_error("a command is required (brdfnav --help lists them)");
    return usage_error(e.what());
  } catch (const brdfnav::Error& e) {
    const int status = exit_status(e.code());
    if (status == 2) return usage_error(e.what());
    std::fprintf(stderr, "brdfnav: error: %s\n", e.what());
    return status;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "brdfnav: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
