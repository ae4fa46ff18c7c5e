// Writing BRDF images: the builder's database images and `brdfnav render`'s output, through
// OpenImageIO. The navigator reads them back with OpenEXR alone (brdfnav/core/image.h);
// their header's keys are database_format.h's.
#pragma once

#include <brdfnav/core/image.h>

#include <filesystem>

namespace brdfnav {

// Throws ImageError unless `path` names an OpenEXR file (ends in .exr, any case): a linear image
// written under another name would be taken for a display-encoded one.
void check_exr_name(const std::filesystem::path& path);
// How write_exr() stores the pixels.
enum class ExrPixels {
  // 32-bit floats, zip-compressed: `brdfnav render`'s output, every bit of the render kept.
  float_zip,
  // 16-bit halves, uncompressed: a database's images. The navigator reads them whenever a
  // thumbnail needs a node it has not cached (a He thumbnail blends 64): a tenth of the time
  // zip-compressed floats take, on the same disk space (docs/NAVIGATION.md, Speed and memory).
  // A half keeps 11 significant bits: 1/4096 relative, about 1/12,000 after the metric's cube
  // root, far below any distance the navigator tells apart.
  half_raw,
};

// Writes linear RGBA OpenEXR atomically: on any failure no file is left behind (and an existing
// file is untouched). `metadata` becomes string attributes of the header. Throws ImageError
// naming the file, or from check_exr_name(); for half_raw, also when a pixel is not finite or
// beyond a half's range (65504), rather than store an infinity.
void write_exr(const Image& image, const std::filesystem::path& path,
               const ImageMetadata& metadata = {}, ExrPixels pixels = ExrPixels::float_zip);

}  // namespace brdfnav
