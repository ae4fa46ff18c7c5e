// `brdfnav precompute`: builds the navigation database (docs/DATABASE.md); `brdfnav db-info`:
// verifies one and prints what it holds.
#include <brdfnav/lookdev/final_images.h>
#include "command_options.h"
#include "commands.h"
#include "progress.h"

#include <brdfnav/core/statistics.h>
#include <brdfnav/precompute/database.h>

#include <algorithm>
#include <cstdio>
#include <stdexcept>
#include <tuple>
#include <vector>

namespace brdfnav::cli {

namespace {

// One progress bar per phase, each line of the log on stderr.
PrecomputeObserver stderr_observer() {
  PrecomputeObserver o;
  o.progress = stderr_progress("");
  o.log = [](const std::string& line) { std::fprintf(stderr, "brdfnav: %s\n", line.c_str()); };
  return o;
}

void print_info(const Database& db) {
  const Manifest& m = db.manifest();
  std::printf("database: %s\nformat: %d\nprofile: %s\nresolution: %d\nscene: %s\n",
              db.dir().string().c_str(), m.format_version, m.profile.c_str(), m.resolution,
              m.scene.c_str());
  std::printf("environment: %s (pixel sha1 %s)\ncomponents: %d\nq nodes: %zu\n", m.env_path.c_str(),
              m.env_pixel_sha1.c_str(), m.components, m.q_nodes.size());
  for (const ProfileGrid& g : m.grids)
    std::printf("model %s: %zu nodes\n", std::string(model_info(g.model).name).c_str(),
                g.grid.node_count());
  // Where the server shows blends as final images (docs/NAVIGATION.md, Final images).
  for (const ProfileGrid& g : m.grids) {
    const std::span<const float> checks = db.blend_checks(g.model);
    const std::string name(model_info(g.model).name);
    if (checks.empty()) {
      const std::string why = !blend_checks_current(m)
                                  ? " usable (format version " + std::to_string(m.format_version) +
                                        ": any check was measured with an earlier spline)"
                                  : "";
      std::printf("blend check %s: none%s; every final image is rendered\n", name.c_str(),
                  why.c_str());
      continue;
    }
    const auto vouched = std::count_if(checks.begin(), checks.end(), [](float d) {
      return d <= lookdev::FinalImages::kFaithfulBlend;
    });
    std::vector<double> values(checks.begin(), checks.end());
    std::printf("blend check %s: %td of %zu cells vouched for (median %.4f, worst %.4f)\n",
                name.c_str(), vouched, checks.size(), quantile(values, 0.5), quantile(values, 1.0));
  }
  std::printf("files: %zu (all checksums verified)\n", m.files.size());
}

// "i/N" -> (i, N); throws Error(invalid_argument) naming --shard unless 0 <= i < N.
std::pair<int, int> parse_shard(const std::string& text) {
  int i = -1, n = 0;
  char end = 0;
  if (std::sscanf(text.c_str(), "%d/%d%c", &i, &n, &end) != 2 || n < 1 || i < 0 || i >= n)
    throw Error(ErrorCode::invalid_argument, "--shard",
                "'" + text + "' is not i/N with 0 <= i < N");
  return {i, n};
}

void add_merge_command(CLI::App& precompute) {
  auto* merge = precompute.add_subcommand(
      "merge",
      "Join the shards of a sharded precompute into the database (embedding, fits, blend check)");
  auto shards = std::make_shared<std::vector<std::string>>();
  auto out = std::make_shared<std::string>();
  auto threads = std::make_shared<int>(0);
  merge->add_option("shards", *shards, "Shard directories (every i of --shard i/N)")->required();
  merge->add_option("--out,-o", *out, "Database directory to create (must not exist)")->required();
  merge->add_option("--threads", *threads, "Worker threads (0: all)")
      ->check(CLI::NonNegativeNumber);
  merge->callback([=] {
    merge_recorded_shards({shards->begin(), shards->end()}, *out, *threads, stderr_observer());
  });
}

}  // namespace

void add_precompute_commands(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "precompute", "Pre-render every model's grid, build the embedding and the conversion fits");
  auto profile = std::make_shared<std::string>("default");
  auto setup = std::make_shared<RenderSetup>();
  auto out = std::make_shared<std::string>();
  auto resume = std::make_shared<bool>(false);
  auto threads = std::make_shared<int>(0);
  auto shard = std::make_shared<std::string>("0/1");
  cmd->add_option("--profile", *profile, "Grid density: smoke, test, default or paper")
      ->capture_default_str()
      ->check(CLI::IsMember(profile_names()));
  add_render_setup_options(*cmd, *setup);
  cmd->get_option("--res")->default_str("the profile's");
  cmd->add_option("--out,-o", *out, "Database (or shard) directory to create (must not exist)");
  cmd->add_flag("--resume", *resume,
                "Reuse the finished work of an interrupted run in OUT.partial");
  cmd->add_option("--threads", *threads, "Worker threads (0: all)")->check(CLI::NonNegativeNumber);
  cmd->add_option("--shard", *shard, "Render only the deterministic part i of N (i/N) as a shard")
      ->capture_default_str();
  cmd->require_subcommand(0, 1);
  add_merge_command(*cmd);
  cmd->callback([=] {
    if (!cmd->get_subcommands().empty()) return;  // `precompute merge` did the work
    if (out->empty()) throw Error(ErrorCode::invalid_argument, "precompute: --out is required");
    PrecomputeRequest request{make_profile(*profile), *out, *resume, *threads, stderr_observer()};
    std::tie(request.shard_index, request.shard_count) = parse_shard(*shard);
    // --res overrides the profile's resolution only when given.
    if (cmd->count("--res") > 0) request.profile.resolution = setup->resolution;
    const EnvMap env = load_env(*setup);
    const Scene geometry = load_scene(*setup);
    precompute_database(request, env, geometry);
  });

  auto* info = app.add_subcommand("db-info", "Verify a database and print what it holds");
  auto dir = std::make_shared<std::string>();
  // --db as every other command; the directory alone, as before, still works.
  info->add_option("--db,dir", *dir, "Database directory (brdfnav precompute)")->required();
  info->callback([=] { print_info(Database::open(*dir)); });
}

}  // namespace brdfnav::cli
