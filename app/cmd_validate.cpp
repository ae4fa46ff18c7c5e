// `brdfnav validate`: the paper's evaluation of its metric (section 2.2: Figures 2, 3, 8 and 9)
// and, given a database, of its embedding; written as report.md, report.yaml and PNG plots
// (docs/VALIDATION.md). Every file is written atomically.
#include "commands.h"
#include "validation_report.h"

#include <brdfnav/core/atomic_file.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <type_traits>

namespace brdfnav::cli {

namespace {

namespace fs = std::filesystem;

const std::string kStudioLights = "/usr/share/blender/datafiles/studiolights/world/";

// Blender's eight studio lights: by default every one is compared with the reference (itself
// left out), so that the report gives Figure 3's full matrix and the most representative map.
std::vector<std::string> studio_lights() {
  std::vector<std::string> paths;
  for (const char* name :
       {"interior", "forest", "courtyard", "city", "night", "studio", "sunrise", "sunset"})
    paths.push_back(kStudioLights + name + ".exr");
  return paths;
}

struct ValidateOptions {
  std::string db;
  std::string reference = kDefaultEnvPath;  // without --db
  std::vector<std::string> envs = studio_lights();
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
  check_output_file((dir / "report.md").string(), "--out");
}

// Runs one study with a line on stderr when it is done (they take seconds to minutes).
template <typename F>
auto timed(const std::string& what, F&& study) {
  const auto start = std::chrono::steady_clock::now();
  const auto done = [&] {
    const std::chrono::duration<double> took = std::chrono::steady_clock::now() - start;
    std::fprintf(stderr, "brdfnav: validate: %s done in %.1f s\n", what.c_str(), took.count());
  };
  if constexpr (std::is_void_v<std::invoke_result_t<F>>) {
    study();
    done();
  } else {
    auto result = study();
    done();
    return result;
  }
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

// The name Figure 3 gives its constant environment.
const std::string kUniform = "uniform";

// Short names for the maps (file stems), unique among themselves and Figure 3's own entries
// (the constant environment, the BRDF-space metric): a name already taken gets a suffix.
std::vector<std::string> map_names(const std::vector<std::string>& paths) {
  std::vector<std::string> taken{kUniform, kBrdfL2Entry}, names;
  for (const std::string& path : paths) {
    const std::string stem = fs::path(path).stem().string();
    std::string name = stem;
    for (int n = 2; std::find(taken.begin(), taken.end(), name) != taken.end(); ++n)
      name = stem + "-" + std::to_string(n);
    taken.push_back(name);
    names.push_back(name);
  }
  return names;
}

bool same_file(const std::string& a, const std::string& b) {
  std::error_code ec;
  return fs::equivalent(a, b, ec) && !ec;
}

// Everything the studies read, loaded before any rendering (and before the output directory is
// made) so that a bad input fails at once and leaves nothing behind. With a database, its own
// map and scene are the reference: the report then speaks of the metric that database embodies.
struct Inputs {
  std::optional<Database> db;
  std::string reference_path;
  EnvMap reference;
  Scene scene;
  std::vector<std::string> other_paths;  // --env without the reference map itself
  std::vector<EnvMap> others;

  explicit Inputs(const ValidateOptions& o)
      : db(o.db.empty() ? std::nullopt : std::optional<Database>(Database::open(o.db))),
        reference_path(db ? db->manifest().env_path : o.reference),
        reference(db ? load_database_env(*db) : EnvMap::load(reference_path)),
        scene(db ? load_scene({.scene = db->manifest().scene}) : Scene::sphere()) {
    for (const std::string& path : o.envs) {
      if (same_file(path, reference_path)) {
        std::fprintf(stderr,
                     "brdfnav: validate: note: %s is the reference map; left out of --env\n",
                     path.c_str());
        continue;
      }
      other_paths.push_back(path);
      others.push_back(EnvMap::load(path));
    }
  }
};

// A map's short name for each input map (map_names), the reference first.
std::vector<std::string> input_names(const Inputs& in) {
  std::vector<std::string> paths{in.reference_path};
  paths.insert(paths.end(), in.other_paths.begin(), in.other_paths.end());
  return map_names(paths);
}

// Figure 2 and Figure 3's distances under each other map, then under a constant environment,
// which shows no highlight shapes (the paper expects it to fail). One renderer at a time: a
// renderer is its map's largest allocation (about 0.8 GB for a 4096 x 2048 map).
void run_other_maps(const Inputs& in, const std::vector<std::string>& names,
                    const SceneSamples& samples, int resolution, ValidationResults& r,
                    std::vector<SceneEntry>& fig3) {
  for (std::size_t i = 0; i < in.others.size(); ++i)
    timed(names[i + 1] + ": figures 2 and 3", [&] {
      Renderer renderer(in.others[i], in.scene, resolution);
      r.fig2_others.push_back({names[i + 1], pellacini_study(renderer)});
      fig3.push_back({names[i + 1], image_distances(renderer, samples.materials), {}});
    });
  constexpr int kUniformHeight = 32;
  const EnvMap uniform(2 * kUniformHeight, kUniformHeight,
                       std::vector<float>(6 * kUniformHeight * kUniformHeight, 1.0f), kUniform);
  Renderer constant(uniform, in.scene, resolution);
  fig3.push_back({kUniform, image_distances(constant, samples.materials), {}});
}

ValidationResults run(const ValidateOptions& o) {
  const Inputs in(o);
  check_writable(o.out);
  ValidationResults r;
  r.resolution = o.resolution;
  r.reference_env = in.reference_path;
  r.scene = in.db ? in.db->manifest().scene : "sphere";
  r.other_envs = in.other_paths;
  r.database = o.db;
  const std::vector<std::string> names = input_names(in);
  const SceneSamples samples = scene_samples();
  std::vector<SceneEntry> fig3;
  {
    Renderer main(in.reference, in.scene, o.resolution);
    timed(names[0] + ": figures 2, 3, 8 and 9", [&] {
      r.fig2 = pellacini_study(main);
      fig3.push_back({names[0], image_distances(main, samples.materials), {}});
      constexpr int kRow = 8;
      r.fig8 = spacing_study(main, ward_sample, log_grid(0.01, 0.37, 32), Baseline::brdf_l2, kRow);
      r.fig9 = spacing_study(main, lafortune_sample, linear_grid(0.54, 0.58, 41), Baseline::linear,
                             kRow);
    });
  }
  run_other_maps(in, names, samples, o.resolution, r, fig3);
  r.fig3 = scene_study(samples, std::move(fig3));
  if (in.db) {
    Renderer exact(in.reference, in.scene, in.db->manifest().resolution);
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
