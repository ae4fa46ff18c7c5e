#include <brdfnav/lookdev/exact_thumbnails.h>

#include <brdfnav/core/lru_cache.h>
#include <brdfnav/lookdev/database_env.h>
#include <brdfnav/navigator/database_format.h>
#include <brdfnav/renderer/render.h>

#include <algorithm>
#include <map>
#include <mutex>
#include <optional>
#include <string>

namespace brdfnav::lookdev {

struct ExactThumbnails::Impl {
  // One resolution's renderer: it renders one image at a time.
  struct Slot {
    std::mutex mutex;
    std::optional<Renderer> renderer;
    std::shared_ptr<const Image> diffuse;  // the renderer's, set with it
  };

  Impl(const Database& db, int res, std::size_t images)
      : database(db),
        resolution(res),
        capacity_pixels(std::max<std::size_t>(1, images) * std::size_t(res) * std::size_t(res)) {}

  const Database& database;
  int resolution;
  std::size_t capacity_pixels;

  std::mutex source_mutex;  // the map and the scene, loaded once for every slot
  std::optional<EnvMap> env;
  std::optional<Scene> scene;
  std::mutex slots_mutex;
  std::map<int, Slot> slots;  // node-based: a slot stays where it is while others are added

  // A lobe's render (rho_s = 1) and the diffuse image of its resolution: what a material of
  // that lobe in any colours is composed of.
  struct LobeImages {
    std::shared_ptr<const Image> specular, diffuse;
  };
  // The cache of lobes' renders by (lobe, resolution), each costing its pixels, least recently
  // used out first.
  std::mutex cache_mutex;
  LruCache<std::string, LobeImages> cache{capacity_pixels};

  std::optional<LobeImages> cached(const std::string& key) {
    const std::lock_guard lock(cache_mutex);
    if (const LobeImages* found = cache.find(key)) return *found;
    return std::nullopt;
  }

  void keep(const std::string& key, const LobeImages& lobe) {
    const std::lock_guard lock(cache_mutex);
    cache.insert(key, lobe, lobe.specular->rgba.size() / 4);
  }

  Slot& slot(int res) {
    const std::lock_guard lock(slots_mutex);
    return slots[res];
  }

  // The database's map, loaded on first use; call with source_mutex held.
  const EnvMap& environment() {
    if (!env) env.emplace(load_database_env(database));
    return *env;
  }

  // The slot's renderer, made on first use; call with the slot's mutex held.
  Renderer& ready_renderer(Slot& s, int res) {
    if (!s.renderer) {
      const Manifest& m = database.manifest();
      {
        const std::lock_guard lock(source_mutex);
        environment();
        if (!scene) scene.emplace(Scene::load(m.scene));
      }
      RenderOptions options;
      try {
        options.quality = quality_from_record(m.render_quality);
      } catch (const RenderError& e) {  // the manifest's knobs: a damaged database, named
        throw DatabaseError((database.dir() / db::kManifestFile).string() + ": " + e.what());
      }
      s.renderer.emplace(*env, *scene, res, options);
      s.diffuse = std::make_shared<const Image>(s.renderer->diffuse());
    }
    return *s.renderer;
  }

  // The render of m's lobe at `res`, cached or made now (Renderer::render composes a material
  // of the same two images, so the colours' offers of a tab share their lobe's one render).
  LobeImages lobe(const Material& m, int res, const std::function<void()>& check) {
    Material shape = m;
    shape.rho_d = Rgb::Zero();
    shape.rho_s = Rgb::Ones();
    const std::string key = std::to_string(res) + " " + format_material_spec(shape);
    if (auto found = cached(key)) return *found;
    Slot& s = slot(res);
    const std::lock_guard lock(s.mutex);
    if (auto found = cached(key)) return *found;  // rendered while this one waited
    if (check) check();
    Renderer& renderer = ready_renderer(s, res);
    // Set for every render, so that none runs with another's check. A throw from it stops the
    // render between rows; the renderer keeps nothing half-made (render.h).
    renderer.set_progress(
        check ? ProgressSink([check](std::string_view, std::size_t, std::size_t) { check(); })
              : ProgressSink());
    const LobeImages made{
        std::make_shared<const Image>(renderer.specular(make_lobe(m.model, m.params))), s.diffuse};
    keep(key, made);
    return made;
  }
};

ExactThumbnails::ExactThumbnails(const Database& database, int resolution, std::size_t cache_images)
    : impl_(std::make_unique<Impl>(database, resolution, cache_images)) {}

ExactThumbnails::~ExactThumbnails() = default;

Image ExactThumbnails::environment_picture(int width) const {
  const std::lock_guard lock(impl_->source_mutex);
  return brdfnav::environment_picture(impl_->environment(), width);
}

int ExactThumbnails::resolution() const {
  return impl_->resolution;
}

std::shared_ptr<const Image> ExactThumbnails::render(const Material& m) const {
  return render(m, impl_->resolution);
}

std::shared_ptr<const Image> ExactThumbnails::render(const Material& m, int resolution,
                                                     const std::function<void()>& check) const {
  validate(m);
  require_render_colorspace(m);
  const Impl::LobeImages lobe = impl_->lobe(m, resolution, check);
  return std::make_shared<const Image>(compose(*lobe.diffuse, *lobe.specular, m.rho_d, m.rho_s));
}

ExactSteps ExactThumbnails::steps_from(const Material& current, int resolution,
                                       std::function<void()> check) const {
  const int res = resolution > 0 ? resolution : impl_->resolution;
  // The current material's image once, not per step: each render() composes its colours anew.
  std::shared_ptr<const Image> from = render(current, res, check);
  ExactSteps steps;
  steps.distance = [this, from = std::move(from), res, check = std::move(check)](
                       const Material& m) { return image_distance(*from, *render(m, res, check)); };
  return steps;
}

}  // namespace brdfnav::lookdev
