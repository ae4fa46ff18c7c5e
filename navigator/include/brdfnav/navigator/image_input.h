// Reading BRDF images' OpenEXR files: a database's images and the header attributes that say how
// each was rendered (brdfnav/core/image.h's db::kHeader*).
#pragma once

#include <brdfnav/core/image.h>

#include <filesystem>
#include <string>

namespace brdfnav {

// What an OpenEXR file's header says: its data window's size and its brdfnav string attributes.
struct ImageHeader {
  int width = 0, height = 0;
  ImageMetadata metadata;  // the string attributes whose names start with "brdfnav:"
  // The attribute's value, or "" when the header has none.
  std::string attribute(const std::string& name) const;
};

// The database's images are OpenEXR, read here with OpenEXR alone (no OpenImageIO: the navigator's
// library must not bring its image libraries into a host; docs/HOSTS.md). The builder writes them
// (brdfnav/renderer/image_output.h).
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

}  // namespace brdfnav
