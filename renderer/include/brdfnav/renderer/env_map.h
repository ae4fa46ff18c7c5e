// Latitude-longitude HDR environment maps: loading (anything OpenImageIO reads), validation and
// the orientation convention shared by every renderer of brdfnav.
//
// Orientation (world: y up; the camera sits on +z looking toward -z, +x to its right):
//   u = 0.5 + atan2(-x, z) / (2 pi),  v = acos(y) / pi,
// with u across the columns (left to right) and v down the rows (row 0 is the zenith). The centre
// of the map (u, v) = (0.5, 0.5) is the direction +z, i.e. toward the camera, so a mirror sphere
// shows the middle of the map in its middle; seen from inside the sphere of directions, u grows
// to the right (the map is not mirrored).
#pragma once

#include <brdfnav/core/error.h>
#include <brdfnav/core/math.h>
#include <brdfnav/core/warning.h>

#include <filesystem>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace brdfnav {

// The map the paper's metric uses unless told otherwise (Debian blender-data, CC0): of Blender's
// eight, the one whose distances agree best with the other seven's (Figure 3; `brdfnav validate`
// names it; docs/VALIDATION.md, "Choosing the default map"). Its one definition: every default
// of the CLI, the tests and the Slurm scripts (which ask `brdfnav precompute --help`) comes from
// here.
inline constexpr const char* kDefaultEnvPath =
    "/usr/share/blender/datafiles/studiolights/world/forest.exr";

// The widest map load() reads: 16384 x 8192 is 1.5 GiB of float RGB, allocated before the pixels
// are read, so a corrupt header that claims more is refused instead of exhausting memory.
inline constexpr int kMaxEnvWidth = 16384;

// A map that cannot be used: the message names the file and what is wrong.
using EnvMapError = LayerError<struct EnvMapErrorTag, ErrorCode::io>;

struct EnvLoadOptions {
  // Replace NaN and infinite texels by 0 (with one warning line) instead of rejecting the map.
  bool sanitize = false;
};

// Negative texel components within this fraction of the map's mean are the ringing of filtered
// or compressed maps (Blender's reach -0.4%): clamped to 0 without a warning.
inline constexpr double kNegligibleNegative = 0.01;

class EnvMap {
 public:
  // Reads the first three channels of subimage 0 as linear RGB. Throws EnvMapError when the file
  // is missing or unreadable, has fewer than 3 channels, is not exactly 2:1, is wider than
  // kMaxEnvWidth, or (without `sanitize`) holds NaN/Inf texels. Negative components are clamped
  // to 0, with one warning when one of them is below -kNegligibleNegative times the mean.
  static EnvMap load(const std::filesystem::path& path, const EnvLoadOptions& options = {},
                     const WarningSink& warn = warn_to_stderr);

  // An in-memory map (synthetic environments, tests): `rgb` holds width * height * 3 finite,
  // non-negative floats, row 0 first; width must be 2 * height. Throws EnvMapError otherwise.
  EnvMap(int width, int height, std::vector<float> rgb, std::string source);

  int width() const { return width_; }
  int height() const { return height_; }
  Rgb texel(int x, int y) const {
    const float* p = &rgb_[3 * (static_cast<std::size_t>(y) * width_ + x)];
    return {p[0], p[1], p[2]};
  }
  const std::vector<float>& pixels() const { return rgb_; }
  // The file path, or the description given to the in-memory constructor.
  const std::string& source() const { return source_; }
  // SHA-1 of the texels as rendered (after clamping/sanitising), for provenance.
  const std::string& pixel_sha1() const { return pixel_sha1_; }

  // World direction of map coordinates (u, v) in [0, 1]^2, and back (see the file comment).
  static Vec3 direction(double u, double v);
  static Vec2 texcoord(const Vec3& direction);

 private:
  int width_ = 0, height_ = 0;
  std::vector<float> rgb_;
  std::string source_, pixel_sha1_;
};

// The map at `path` whose texels a build recorded (`pixel_sha1`), loaded as every build loaded
// it: NaN/Inf texels set to 0, as a --sanitize-env build did (a map that needed it could not have
// been built without). `recorder` names the file that records the map (a database's manifest, a
// shard's shard.yaml), for the error. Throws EnvMapError with ErrorCode::database naming the map
// and `recorder` when the file can no longer be read or its texels have changed since.
EnvMap load_recorded_env(const std::string& path, const std::string& pixel_sha1,
                         const std::string& recorder);

// The map's Rec. 709 luminance over the sphere of directions: each texel's times its exact solid
// angle, summed (over 4 pi, the map's mean luminance). The renderer's hot texels are those
// brighter than a multiple of that mean (env_pyramid.cpp, which defines it with the texels' solid
// angles); `brdfnav validate` reports the map's peak against it (studies/src/validation.cpp).
double luminance_power(const EnvMap& env);

}  // namespace brdfnav
