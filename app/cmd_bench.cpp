// `brdfnav bench`: its subcommands and their options. The benchmarks themselves are bench/cli's
// (brdfnav::cli_benchmarks): render (the pre-renderer's speed and accuracy), navigator (the
// neighbour service), fidelity (what the artist sees against exact renders), load (concurrent
// queries) and fits (the conversion fits). With --json FILE, render, fits, navigator and
// fidelity also write the figures bench/results.py compares with their targets.
#include "bench_fidelity.h"
#include "bench_fits.h"
#include "bench_load.h"
#include "bench_navigator.h"
#include "bench_render.h"
#include "command_options.h"
#include "commands.h"

#include <brdfnav/core/models.h>

#include <memory>

namespace brdfnav::cli {

namespace {

void add_json_option(CLI::App& command, std::string& path) {
  command.add_option("--json", path, "Also write the figures to this JSON file (bench/results.py)");
}

}  // namespace

void add_bench_commands(CLI::App& app) {
  auto* bench = app.add_subcommand("bench", "Measure brdfnav on this machine");
  bench->require_subcommand(1);
  auto* render = bench->add_subcommand(
      "render", "ms per image and accuracy ratio (vs 16x the samples) per model and setting");
  auto o = std::make_shared<RenderBenchOptions>();
  o->setup.resolution = 128;
  add_render_setup_options(*render, o->setup);
  render->add_option("--model", o->model, "Only this model");
  render->add_option("--repeats", o->repeats, "Timed renders per setting")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  render->add_flag("!--no-accuracy", o->accuracy, "Skip the accuracy ratios (timing only)");
  render->add_flag("--anisotropic", o->anisotropic,
                   "Also the strongly anisotropic Ward settings (slow: their references are)");
  add_json_option(*render, o->json);
  render->callback([o] {
    if (!o->model.empty() && !find_model(o->model))
      throw Error(ErrorCode::invalid_argument, "--model", "unknown model '" + o->model + "'");
    run_render_bench(*o);
  });

  auto* nav = bench->add_subcommand(
      "navigator", "Latency per tab, thumbnails through OCIO and memory with a database open");
  auto n = std::make_shared<NavigatorBenchOptions>();
  nav->add_option("--db", n->db, "Database directory")->required();
  nav->add_option("--radius", n->radius, "Radius eps")
      ->capture_default_str()
      ->check(radius_validator());
  nav->add_option("--materials", n->materials, "Random materials per model")
      ->capture_default_str()
      ->check(CLI::Range(1, 100000));
  nav->add_option("--thumbnail-size", n->thumbnail_size, "Thumbnail width and height")
      ->capture_default_str()
      ->check(CLI::Range(8, 1024));
  nav->add_option("--cache-mib", n->cache_mib, "The thumbnails' image cache budget (MiB)")
      ->capture_default_str()
      ->check(CLI::Range(1, 65536));
  add_json_option(*nav, n->json);
  nav->callback([n] { run_navigator_bench(*n); });

  auto* fidelity = bench->add_subcommand(
      "fidelity", "Thumbnails and steps of every tab against exact renders, per model");
  auto f = std::make_shared<FidelityBenchOptions>();
  fidelity->add_option("--db", f->db, "Database directory")->required();
  fidelity->add_option("--radius", f->radius, "Radius eps")
      ->capture_default_str()
      ->check(radius_validator());
  fidelity->add_flag("--exact", f->exact, "Steps moved to eps by rendering, as serve does");
  fidelity->add_option("--materials", f->materials, "Random materials per model")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000));
  add_json_option(*fidelity, f->json);
  fidelity->callback([f] { run_fidelity_bench(*f); });

  auto* load = bench->add_subcommand(
      "load", "Threads querying one database: queries/s, answers vs serial, resident memory");
  auto l = std::make_shared<LoadBenchOptions>();
  load->add_option("--db", l->db, "Database directory")->required();
  load->add_option("--threads", l->threads, "Querying threads")
      ->capture_default_str()
      ->check(CLI::Range(1, 256));
  load->add_option("--queries", l->queries, "Queries per thread")
      ->capture_default_str()
      ->check(CLI::Range(1, 100000000));
  load->callback([l] { run_load_bench(*l); });

  auto* fits = bench->add_subcommand("fits", "Time the model-to-model conversion fits (paper, 4)");
  auto per_model = std::make_shared<int>(8);
  auto fits_json = std::make_shared<std::string>();
  fits->add_option("--per-model", *per_model, "Source grid nodes per model and target")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000));
  add_json_option(*fits, *fits_json);
  fits->callback([per_model, fits_json] { run_fit_bench(*per_model, *fits_json); });
}

}  // namespace brdfnav::cli
