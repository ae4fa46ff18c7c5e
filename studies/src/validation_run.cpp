#include <brdfnav/lookdev/database_env.h>
#include <brdfnav/studies/validation_run.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <type_traits>

namespace brdfnav {

namespace {

namespace fs = std::filesystem;

const std::string kStudioLights = "/usr/share/blender/datafiles/studiolights/world/";

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

// A map's short name for each input map (map_names), the reference first.
std::vector<std::string> input_names(const ValidationInputs& in) {
  std::vector<std::string> paths{in.reference_path};
  paths.insert(paths.end(), in.other_paths.begin(), in.other_paths.end());
  return map_names(paths);
}

// Figure 2 and Figure 3's distances under each other map, then under a constant environment,
// which shows no highlight shapes (the paper expects it to fail). One renderer at a time: a
// renderer is its map's largest allocation (about 0.8 GB for a 4096 x 2048 map).
void run_other_maps(const ValidationInputs& in, const std::vector<std::string>& names,
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

}  // namespace

std::vector<std::string> studio_lights() {
  std::vector<std::string> paths;
  for (const char* name :
       {"interior", "forest", "courtyard", "city", "night", "studio", "sunrise", "sunset"})
    paths.push_back(kStudioLights + name + ".exr");
  return paths;
}

ValidationInputs::ValidationInputs(const std::string& database, const std::string& reference_map,
                                   const std::vector<std::string>& envs)
    : database_path(database),
      db(database.empty() ? std::nullopt : std::optional<Database>(Database::open(database))),
      reference_path(db ? db->manifest().env_path : reference_map),
      reference(db ? load_database_env(*db) : EnvMap::load(reference_path)),
      scene(db ? Scene::load(db->manifest().scene) : Scene::sphere()) {
  for (const std::string& path : envs) {
    if (same_file(path, reference_path)) {
      std::fprintf(stderr, "brdfnav: validate: note: %s is the reference map; left out of --env\n",
                   path.c_str());
      continue;
    }
    other_paths.push_back(path);
    others.push_back(EnvMap::load(path));
  }
}

ValidationResults run_validation(const ValidationInputs& in, const ValidationSizes& sizes) {
  ValidationResults r;
  r.resolution = sizes.resolution;
  r.reference_env = in.reference_path;
  r.scene = in.db ? in.db->manifest().scene : "sphere";
  r.other_envs = in.other_paths;
  r.database = in.database_path;
  const std::vector<std::string> names = input_names(in);
  const SceneSamples samples = scene_samples();
  std::vector<SceneEntry> fig3;
  {
    Renderer main(in.reference, in.scene, sizes.resolution);
    timed(names[0] + ": figures 2, 3, 8 and 9", [&] {
      r.fig2 = pellacini_study(main);
      fig3.push_back({names[0], image_distances(main, samples.materials), {}});
      constexpr int kRow = 8;
      r.fig8 = spacing_study(main, ward_sample, log_grid(0.01, 0.37, 32), Baseline::brdf_l2, kRow);
      r.fig9 = spacing_study(main, lafortune_sample, linear_grid(0.54, 0.58, 41), Baseline::linear,
                             kRow);
    });
  }
  run_other_maps(in, names, samples, sizes.resolution, r, fig3);
  r.fig3 = scene_study(samples, std::move(fig3));
  if (in.db) {
    Renderer exact(in.reference, in.scene, in.db->manifest().resolution);
    r.embedding = timed("embedding", [&] { return embedding_study(*in.db, exact, sizes.pairs); });
    r.fits = timed("fits", [&] { return fit_study(*in.db, sizes.fit_samples); });
  }
  return r;
}

}  // namespace brdfnav
