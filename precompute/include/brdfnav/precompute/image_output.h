// Writing BRDF images: the builder's database images and `brdfnav render`'s output, through
// OpenImageIO. The navigator reads them back with OpenEXR alone (brdfnav/navigator/image.h);
// their header's keys are database_format.h's.
#pragma once

#include <brdfnav/navigator/image.h>

#include <filesystem>

namespace brdfnav {

// Throws ImageError unless `path` names an OpenEXR file (ends in .exr, any case): a linear image
// written under another name would be taken for a display-encoded one.
void check_exr_name(const std::filesystem::path& path);
// Writes linear float RGBA OpenEXR (zip) atomically: on any failure no file is left behind (and
// an existing file is untouched). `metadata` becomes string attributes of the header. Throws
// ImageError naming the file, or from check_exr_name().
void write_exr(const Image& image, const std::filesystem::path& path,
               const ImageMetadata& metadata = {});

}  // namespace brdfnav
