#include "exact_thumbnails.h"

#include <brdfnav/precompute/database.h>
#include <brdfnav/precompute/profile.h>
#include <brdfnav/precompute/render.h>

#include <algorithm>
#include <optional>

namespace brdfnav::cli {

struct ExactThumbnails::Impl {
  Impl(const Database& db, int res, std::size_t images)
      : database(db), resolution(res), capacity(std::max<std::size_t>(1, images)) {}

  const Database& database;
  int resolution;
  std::size_t capacity;
  std::mutex render_mutex;  // the renderer renders one image at a time
  std::optional<EnvMap> env;
  std::optional<Scene> scene;
  std::optional<Renderer> renderer;
  std::mutex cache_mutex;
  std::map<std::string, std::pair<std::shared_ptr<const Image>, std::list<std::string>::iterator>>
      cache;
  std::list<std::string> uses;  // most recently used first

  std::shared_ptr<const Image> cached(const std::string& key) {
    const std::lock_guard lock(cache_mutex);
    const auto it = cache.find(key);
    if (it == cache.end()) return nullptr;
    uses.splice(uses.begin(), uses, it->second.second);
    return it->second.first;
  }

  void keep(const std::string& key, std::shared_ptr<const Image> image) {
    const std::lock_guard lock(cache_mutex);
    if (cache.contains(key)) return;
    uses.push_front(key);
    cache.emplace(key, std::make_pair(std::move(image), uses.begin()));
    while (cache.size() > capacity) {
      cache.erase(uses.back());
      uses.pop_back();
    }
  }

  Renderer& ready_renderer() {
    if (!renderer) {
      const Manifest& m = database.manifest();
      env.emplace(load_database_env(database));
      scene.emplace(Scene::load(m.scene));
      RenderOptions options;
      options.quality = make_profile(m.profile).quality;
      renderer.emplace(*env, *scene, resolution, options);
    }
    return *renderer;
  }
};

ExactThumbnails::ExactThumbnails(const Database& database, int resolution, std::size_t cache_images)
    : impl_(std::make_unique<Impl>(database, resolution, cache_images)) {}

ExactThumbnails::~ExactThumbnails() = default;

std::shared_ptr<const Image> ExactThumbnails::render(const Material& m) const {
  validate(m);
  const std::string key = format_material_spec(m);
  if (auto image = impl_->cached(key)) return image;
  const std::lock_guard lock(impl_->render_mutex);
  if (auto image = impl_->cached(key)) return image;  // rendered while this one waited
  auto image = std::make_shared<const Image>(impl_->ready_renderer().render(m));
  impl_->keep(key, image);
  return image;
}

ExactSteps ExactThumbnails::steps_from(const Material& current) const {
  ExactSteps steps;
  steps.distance = [this, current](const Material& m) {
    return image_distance(*render(current), *render(m));
  };
  return steps;
}

}  // namespace brdfnav::cli
