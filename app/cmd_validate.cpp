// `brdfnav validate` (issue #7): the paper's evaluation of its metric (section 2.2: Figures 2, 3,
// 8 and 9) and, given a database, of its embedding; written as report.md, report.yaml and PNG
// plots (docs/VALIDATION.md). Every file is written atomically.
#include "commands.h"
#include "validation_report.h"

#include <brdfnav/core/atomic_file.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>
#include <optional>

namespace brdfnav::cli {

namespace {

namespace fs = std::filesystem;

const std::string kStudioLights = "/usr/share/blender/datafiles/studiolights/world/";

struct ValidateOptions {
  std::string db;
  std::vector<std::string> envs{kStudioLights + "forest.exr", kStudioLights + "courtyard.exr"};
  int resolution = 128;
  int pairs = 50;
  int fit_samples = 20;
  std::string out;
};

// Fails before any rendering when the report cannot be written.
void check_writable(const fs::path& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir))
    throw std::runtime_error("--out " + dir.string() + ": cannot create the directory" +
                             (ec ? ": " + ec.message() : ""));
  const AtomicOutput probe(dir / "report.md");  // removes its temporary file
  if (!std::ofstream(probe.temp_path()))
    throw std::runtime_error("--out " + dir.string() + ": the directory is not writable");
}

// Runs one study with a line on stderr when it is done (they take seconds to minutes).
template <typename F>
auto timed(const char* what, F&& study) {
  const auto start = std::chrono::steady_clock::now();
  auto result = study();
  const std::chrono::duration<double> took = std::chrono::steady_clock::now() - start;
  std::fprintf(stderr, "brdfnav: validate: %s done in %.1f s\n", what, took.count());
  return result;
}

std::vector<double> log_grid(double lo, double hi, int count) {
  std::vector<double> v;
  for (int i = 0; i < count; ++i) v.push_back(lo * std::pow(hi / lo, double(i) / (count - 1)));
  return v;
}
std::vector<double> linear_grid(double lo, double hi, int count) {
  std::vector<double> v;
  for (int i = 0; i < count; ++i) v.push_back(lo + (hi - lo) * i / (count - 1));
  return v;
}

Material lafortune_sample(double cz) {
  Material m = ward_sample(0.1);  // the figures' colours
  m.model = ModelId::lafortune;
  m.params = {cz, 800};
  return m;
}

// Everything the studies read, loaded before any rendering (and before the output directory is
// made) so that a bad input fails at once and leaves nothing behind.
struct Inputs {
  EnvMap reference = EnvMap::load(kDefaultEnvPath);
  std::vector<EnvMap> others;
  std::optional<Database> db;
  std::optional<EnvMap> db_env;
  std::optional<Scene> db_scene;
  Scene sphere = Scene::sphere();

  explicit Inputs(const ValidateOptions& o) {
    for (const std::string& path : o.envs) others.push_back(EnvMap::load(path));
    if (o.db.empty()) return;
    db = Database::open(o.db);
    db_env = EnvMap::load(db->manifest().env_path);
    SceneOptions scene;
    scene.scene = db->manifest().scene;
    db_scene = load_scene(scene);
  }
};

// Figure 3's renderers: the reference, every other map and a constant environment, which shows
// no highlight shapes (the paper expects it to fail).
SceneStudy run_fig3(const Inputs& in, Renderer& reference, int resolution) {
  constexpr int kUniformHeight = 32;
  const EnvMap uniform(2 * kUniformHeight, kUniformHeight,
                       std::vector<float>(6 * kUniformHeight * kUniformHeight, 1.0f), "uniform");
  std::vector<const EnvMap*> envs;
  for (const EnvMap& e : in.others) envs.push_back(&e);
  envs.push_back(&uniform);
  std::vector<std::unique_ptr<Renderer>> renderers;
  std::vector<NamedRenderer> named{{fs::path(kDefaultEnvPath).stem().string(), &reference}};
  for (const EnvMap* env : envs) {
    renderers.push_back(std::make_unique<Renderer>(*env, in.sphere, resolution));
    named.push_back({fs::path(env->source()).stem().string(), renderers.back().get()});
  }
  return scene_study(named);
}

ValidationResults run(const ValidateOptions& o) {
  const Inputs in(o);
  check_writable(o.out);
  ValidationResults r;
  r.resolution = o.resolution;
  r.reference_env = kDefaultEnvPath;
  r.other_envs = o.envs;
  r.database = o.db;
  Renderer main(in.reference, in.sphere, o.resolution);
  r.fig2 = timed("figure 2", [&] { return pellacini_study(main); });
  r.fig3 = timed("figure 3", [&] { return run_fig3(in, main, o.resolution); });
  constexpr int kRow = 8;
  r.fig8 = timed("figure 8", [&] {
    return spacing_study(main, ward_sample, log_grid(0.01, 0.37, 32), Baseline::brdf_l2, kRow);
  });
  r.fig9 = timed("figure 9", [&] {
    return spacing_study(main, lafortune_sample, linear_grid(0.54, 0.58, 41), Baseline::linear,
                         kRow);
  });
  if (in.db) {
    Renderer exact(*in.db_env, *in.db_scene, in.db->manifest().resolution);
    r.embedding = timed("embedding", [&] { return embedding_study(*in.db, exact, o.pairs); });
    r.fits = timed("fits", [&] { return fit_study(*in.db, o.fit_samples); });
  }
  return r;
}

}  // namespace

void add_validate_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "validate", "Reproduce the paper's metric evaluation (Figures 2, 3, 8, 9) as a report");
  auto o = std::make_shared<ValidateOptions>();
  cmd->add_option("--db", o->db, "Database whose embedding to evaluate (optional)");
  cmd->add_option("--env", o->envs, "Environment maps compared with interior.exr (comma-separated)")
      ->delimiter(',')
      ->capture_default_str();
  cmd->add_option("--res", o->resolution, "Image width and height in pixels")
      ->capture_default_str()
      ->check(CLI::Range(8, 4096));
  cmd->add_option("--pairs", o->pairs, "Random material pairs for the embedding's error")
      ->capture_default_str()
      ->check(CLI::Range(2, 100000));
  cmd->add_option("--fit-samples", o->fit_samples,
                  "Nodes per model converted both in BRDF space and in the image metric")
      ->capture_default_str()
      ->check(CLI::Range(1, 100000));
  cmd->add_option("--out,-o", o->out, "Report directory (created if missing)")->required();
  cmd->callback([o] {
    const ocio::ColorPipeline colour;
    const ValidationResults r = run(*o);
    const fs::path dir(o->out);
    const std::vector<ReportFile> files = write_report_plots(dir, r, colour);
    write_file_atomic(dir / "report.yaml", report_yaml(r, files));
    write_file_atomic(dir / "report.md", report_markdown(r, files));
    std::printf("Wrote %s (and report.yaml, %zu plots)\n", (dir / "report.md").c_str(),
                files.size());
  });
}

}  // namespace brdfnav::cli
