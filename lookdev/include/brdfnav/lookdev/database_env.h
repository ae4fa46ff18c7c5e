// The environment map a database's images were rendered under, for whatever renders against a
// database (exact thumbnails, exports, validate's exact distances): the one map check of every
// reader of a database.
#pragma once

#include <brdfnav/core/image.h>
#include <brdfnav/navigator/database.h>
#include <brdfnav/renderer/env_map.h>

namespace brdfnav {

// Loaded from the manifest's path (NaN/Inf texels set to 0, as a --sanitize-env build did) and
// checked against the manifest's pixel SHA-1 (load_recorded_env). Throws EnvMapError with
// ErrorCode::database naming the map and the manifest when the file has changed since the build
// or can no longer be read.
EnvMap load_database_env(const Database& db);

// A picture of `env` for people (the page's lighting): the lat-long map `width` x width / 2,
// each pixel the mean of the texels that fall in it, exposed so that the map's mean luminance
// over the sphere of directions is 0.18 (mid grey), alpha 1. Linear RGB in the renderer's
// colour space: display it through display_encode(). Error (invalid_argument) for a width below 2
// or above the map's.
Image environment_picture(const EnvMap& env, int width);

}  // namespace brdfnav
