#include <brdfnav/navigator/thumbnails.h>

#include <brdfnav/core/parallel_for.h>
#include <brdfnav/navigator/image_input.h>

#include <algorithm>
#include <vector>

namespace brdfnav {

namespace {

// `image` resampled to `size` x `size` (resample(): the filters OpenImageIO's resize chose, which
// the thumbnails used before); the mask is made 0/1 again.
Image resampled(const Image& image, int size) {
  if (image.width == size && image.height == size) return image;
  Image out = resample(image, size, size);
  for (std::size_t i = 3; i < out.rgba.size(); i += 4) out.rgba[i] = out.rgba[i] > 0.5f ? 1.f : 0.f;
  return out;
}

std::size_t pixel_bytes(const Image& image) {
  return image.rgba.size() * sizeof(float);
}

}  // namespace

Thumbnails::Thumbnails(const Database& database, int resolution, std::size_t cache_bytes)
    : database_(database),
      resolution_(resolution > 0 ? resolution : database.manifest().resolution),
      cache_(cache_bytes) {}

std::size_t Thumbnails::cached_bytes() const {
  std::lock_guard lock(mutex_);
  return cache_.total();
}

std::vector<std::shared_ptr<const Image>> Thumbnails::images(const std::vector<Key>& keys) const {
  std::vector<std::shared_ptr<const Image>> out(keys.size());
  std::vector<std::size_t> missing;
  {
    std::lock_guard lock(mutex_);
    for (std::size_t i = 0; i < keys.size(); ++i) {
      if (const auto* image = cache_.find(keys[i])) {
        out[i] = *image;
      } else {
        missing.push_back(i);
      }
    }
  }
  // Read outside the lock, so that other threads' thumbnails need not wait for these files, and
  // on every core: decoding the files is most of a first view (a He thumbnail blends 64).
  parallel_for(missing.size(), worker_threads(0),
               [&](std::size_t j) { out[missing[j]] = read(keys[missing[j]]); });
  for (std::size_t i : missing) out[i] = keep(keys[i], std::move(out[i]));
  return out;
}

std::shared_ptr<const Image> Thumbnails::read(Key key) const {
  const auto path = key.first < 0
                        ? database_.diffuse_path()
                        : database_.image_path(static_cast<ModelId>(key.first), key.second);
  try {
    return std::make_shared<const Image>(resampled(read_image(path), resolution_));
  } catch (const ImageError& e) {
    throw DatabaseError(e.what());
  }
}

std::shared_ptr<const Image> Thumbnails::keep(Key key, std::shared_ptr<const Image> image) const {
  std::lock_guard lock(mutex_);
  // A render in progress keeps its images through its shared_ptr; dropping them from the cache
  // only means the next render reads them again. An image read twice: the first one kept wins.
  const std::size_t bytes = pixel_bytes(*image);
  return cache_.insert(key, std::move(image), bytes);
}

Image Thumbnails::render(const Material& m) const {
  validate(m);
  require_render_colorspace(m);
  const ModelEmbedding* embedding = database_.embedding(m.model);
  if (!embedding)
    throw DatabaseError(database_.dir().string() + ": holds no model '" +
                        std::string(model_info(m.model).name) + "'");
  const std::vector<ParamGrid::Corner> corners = embedding->grid().cubic_corners(m.params);
  std::vector<Key> keys{kDiffuse};
  for (const ParamGrid::Corner& c : corners) keys.push_back({static_cast<int>(m.model), c.node});
  const std::vector<std::shared_ptr<const Image>> images = this->images(keys);
  std::vector<const Image*> specular;
  for (std::size_t k = 0; k < corners.size(); ++k) specular.push_back(images[k + 1].get());
  return blend_images(*images[0], corners, specular, m.rho_d, m.rho_s);
}

}  // namespace brdfnav
