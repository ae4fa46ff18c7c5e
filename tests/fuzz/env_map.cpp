// Fuzz target: an environment map file (EnvMap::load, through OpenImageIO).
//
// The input is saved under the extension of the format its first bytes announce (OpenEXR unless
// it starts like Radiance HDR, PFM or TIFF, the formats HDR maps come in), and OpenImageIO is
// told to use only that reader. By default OpenImageIO would then try every reader it has
// (DICOM, FFmpeg, RAW, ...) on bytes the first one refused, at a few inputs per second and far
// from anything an environment map is. Rejections are EnvMapError.
#include "fuzz_target.h"

#include <brdfnav/renderer/env_map.h>

#include <OpenImageIO/imageio.h>

namespace {

const char* extension_of(std::string_view bytes) {
  if (bytes.starts_with("#?")) return ".hdr";
  if (bytes.starts_with("PF") || bytes.starts_with("Pf")) return ".pfm";
  if (bytes.starts_with("II*") || bytes.starts_with("MM\0*")) return ".tif";
  return ".exr";
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace brdfnav;
  [[maybe_unused]] static const bool one_reader = OIIO::attribute("try_all_readers", 0);
  const std::string_view bytes = fuzz::as_text(data, size);
  const std::filesystem::path path =
      fuzz::scratch_dir() / ("env" + std::string(extension_of(bytes)));
  fuzz::write_file(path, bytes);
  try {
    // sanitize: NaN/Inf texels go on to the clamping and hashing instead of stopping early.
    EnvMap::load(path, {.sanitize = true}, [](const std::string&) {});
  } catch (const EnvMapError&) {
  }
  std::filesystem::remove(path);
  return 0;
}
