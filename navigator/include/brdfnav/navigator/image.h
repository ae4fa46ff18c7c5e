// BRDF images in memory and on disk, and the paper's metric between them (section 2.1):
//   d(A, B) = sqrt(mean over covered pixels and the 3 channels of (cbrt(A) - cbrt(B))^2).
// The RMS form makes a radius mean the same at any resolution; it is brdfnav's unit of distance.
#pragma once

#include <brdfnav/core/error.h>
#include <brdfnav/core/math.h>

#include <filesystem>
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

// What an OpenEXR file's header says: its data window's size and its brdfnav string attributes.
struct ImageHeader {
  int width = 0, height = 0;
  ImageMetadata metadata;  // the string attributes whose names start with "brdfnav:"
  // The attribute's value, or "" when the header has none.
  std::string attribute(const std::string& name) const;
};

// The database's images are OpenEXR, read here with OpenEXR alone (no OpenImageIO: the navigator's
// library must not bring its image libraries into a host; docs/HOSTS.md). The builder writes them
// (brdfnav/precompute/image_output.h).
//
// Reads the header of an OpenEXR file. Throws ImageError naming the file when it is missing, not
// an OpenEXR file, or unreadable.
ImageHeader read_image_header(const std::filesystem::path& path);
// Reads an OpenEXR image's R, G, B and A channels as linear float RGBA (without A, alpha is 1).
// Throws ImageError naming the file when it cannot, when it is not OpenEXR or its colour channels
// hold integers (not radiance), or naming the pixel when one is negative or not finite.
Image read_image(const std::filesystem::path& path);
// The string attributes of an OpenEXR file's header that start with "brdfnav:".
ImageMetadata read_image_metadata(const std::filesystem::path& path);

// `image` resampled to `width` x `height`, every channel alike, each axis by a separable filter:
// when shrinking, Lanczos-3 with its support widened by the ratio (so every source pixel
// contributes); when enlarging, Blackman-Harris over 3 source pixels. Those are the filters
// OpenImageIO's ImageBufAlgo::resize() chooses by default, which the thumbnails used before. The
// weights of each output pixel are normalised (a constant stays constant) and the edges clamped.
// Lanczos' lobes may overshoot: values can leave the source's range near sharp edges.
Image resample(const Image& image, int width, int height);

}  // namespace brdfnav
