// `brdfnav validate`: the paper's evaluation of its metric (section 2.2: Figures 2, 3, 8 and 9)
// and, given a database, of its embedding; written as report.md, report.yaml and PNG plots
// (docs/VALIDATION.md). Every file is written atomically. The command parses the options; the
// studies, their inputs and the report are the studies room's (studies/, brdfnav::studies).
#include "command_options.h"
#include "commands.h"

#include <brdfnav/core/atomic_file.h>
#include <brdfnav/studies/validation_report.h>
#include <brdfnav/studies/validation_run.h>

#include <cstdio>
#include <memory>

namespace brdfnav::cli {

namespace {

namespace fs = std::filesystem;

struct ValidateOptions {
  std::string db;
  std::string reference = kDefaultEnvPath;  // without --db
  std::vector<std::string> envs = studio_lights();
  ValidationSizes sizes;
  std::string out;
};

// Fails before any rendering when the report cannot be written.
void check_writable(const fs::path& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir))
    throw Error(ErrorCode::io, "--out " + dir.string() + ": cannot create the directory" +
                                   (ec ? ": " + ec.message() : ""));
  check_output_file((dir / "report.md").string(), "--out");
}

ValidationResults run(const ValidateOptions& o) {
  const ValidationInputs in(o.db, o.reference, o.envs);
  check_writable(o.out);
  return run_validation(in, o.sizes);
}

}  // namespace

void add_validate_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "validate", "Reproduce the paper's metric evaluation (Figures 2, 3, 8, 9) as a report");
  auto o = std::make_shared<ValidateOptions>();
  auto* db = cmd->add_option(
      "--db", o->db,
      "Database whose embedding to evaluate (optional); its map and scene become the reference");
  cmd->add_option("--reference", o->reference,
                  "Reference environment map (the metric's), without --db")
      ->capture_default_str()
      ->excludes(db);
  cmd->add_option("--env", o->envs,
                  "Environment maps compared with the reference (comma-separated; the "
                  "reference itself is left out)")
      ->delimiter(',')
      ->capture_default_str();
  cmd->add_option("--res", o->sizes.resolution, "Image width and height in pixels")
      ->capture_default_str()
      ->check(CLI::Range(8, 4096));
  cmd->add_option("--pairs", o->sizes.pairs, "Random material pairs for the embedding's error")
      ->capture_default_str()
      ->check(CLI::Range(2, 100000));
  cmd->add_option("--fit-samples", o->sizes.fit_samples,
                  "Nodes per model converted both in BRDF space and in the image metric")
      ->capture_default_str()
      ->check(CLI::Range(1, 100000));
  cmd->add_option("--out,-o", o->out, "Report directory (created if missing)")->required();
  cmd->callback([o] {
    const ocio::ColorPipeline color;
    const ValidationResults r = run(*o);
    const fs::path dir(o->out);
    const std::vector<ReportFile> files = write_report_plots(dir, r, color);
    write_file_atomic(dir / "report.yaml", report_yaml(r, files));
    write_file_atomic(dir / "report.md", report_markdown(r, files));
    std::printf("Wrote %s (and report.yaml, %zu plots)\n", (dir / "report.md").c_str(),
                files.size());
  });
}

}  // namespace brdfnav::cli
