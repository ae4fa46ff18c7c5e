// BRDF images in memory and the paper's metric between them (section 2.1):
//   d(A, B) = sqrt(mean over covered pixels and the 3 channels of (cbrt(A) - cbrt(B))^2).
// The RMS form makes a radius mean the same at any resolution; it is brdfnav's unit of distance.
#pragma once

#include <brdfnav/core/error.h>
#include <brdfnav/core/math.h>

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace brdfnav {

// Unreadable image, mismatched sizes or masks; names the file when there is one.
using ImageError = LayerError<struct ImageErrorTag, ErrorCode::io>;

// Linear float RGBA, row 0 at the top. Alpha is coverage (0 or 1): the metric's mask.
struct Image {
  int width = 0, height = 0;
  std::vector<float> rgba;

  Image() = default;
  Image(int w, int h) : width(w), height(h), rgba(static_cast<std::size_t>(w) * h * 4, 0.f) {}

  float* pixel(int x, int y) { return &rgba[4 * (static_cast<std::size_t>(y) * width + x)]; }
  const float* pixel(int x, int y) const {
    return &rgba[4 * (static_cast<std::size_t>(y) * width + x)];
  }
  bool covered(int x, int y) const { return pixel(x, y)[3] > 0.5f; }
};

// rho_d * diffuse + rho_s * specular per channel (computed in double, stored as float); alpha is
// the common mask. Throws ImageError when sizes or masks differ.
Image compose(const Image& diffuse, const Image& specular, const Rgb& rho_d, const Rgb& rho_s);

// Throws ImageError when the sizes or the masks (alpha) differ: what every metric checks first.
void check_same_shape(const Image& a, const Image& b);

// The metric. Throws ImageError when the sizes or the masks (alpha) differ, or no pixel is covered.
double image_distance(const Image& a, const Image& b);

// Metadata written as string attributes of the EXR header (e.g. {db::kHeaderMaterial, spec}).
using ImageMetadata = std::vector<std::pair<std::string, std::string>>;

// Files hold BRDF images as OpenEXR: the renderer writes them (brdfnav/renderer/image_output.h),
// the navigator reads them with OpenEXR alone (brdfnav/navigator/image_input.h).
namespace db {
// The string attributes of every BRDF image's OpenEXR header: how it was rendered. The renderer
// writes them (render_metadata()); Database::open() checks the environment's hash, the scene and
// a grid image's material against the manifest. Part of a database's layout (database_format.h),
// defined here because the renderer and the navigator both need them and neither uses the other.
inline constexpr const char* kHeaderPrefix = "brdfnav:";           // every key starts with it
inline constexpr const char* kHeaderEnv = "brdfnav:env";           // the map's path
inline constexpr const char* kHeaderEnvSha1 = "brdfnav:env_sha1";  // its pixels' SHA-1
inline constexpr const char* kHeaderScene = "brdfnav:scene";       // the scene's description
inline constexpr const char* kHeaderResolution = "brdfnav:resolution";
inline constexpr const char* kHeaderRendererRevision = "brdfnav:renderer_revision";
inline constexpr const char* kHeaderQuality = "brdfnav:quality";  // the render quality settings
// The material spec (format_material_spec()); absent from the diffuse image.
inline constexpr const char* kHeaderMaterial = "brdfnav:material";
}  // namespace db

// `image` resampled to `width` x `height`, every channel alike, each axis by a separable filter:
// when shrinking, Lanczos-3 with its support widened by the ratio (so every source pixel
// contributes); when enlarging, Blackman-Harris over 3 source pixels. Those are the filters
// OpenImageIO's ImageBufAlgo::resize() chooses by default, which the thumbnails used before. The
// weights of each output pixel are normalised (a constant stays constant) and the edges clamped.
// Lanczos' lobes may overshoot: values can leave the source's range near sharp edges.
Image resample(const Image& image, int width, int height);

}  // namespace brdfnav
