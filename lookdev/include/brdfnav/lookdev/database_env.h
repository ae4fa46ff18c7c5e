// The environment map a database's images were rendered under, for whatever renders against a
// database (exact thumbnails, exports, validate's exact distances): the one map check of every
// reader of a database.
#pragma once

#include <brdfnav/navigator/database.h>
#include <brdfnav/renderer/env_map.h>

namespace brdfnav {

// Loaded from the manifest's path (NaN/Inf texels set to 0, as a --sanitize-env build did) and
// checked against the manifest's pixel SHA-1 (load_recorded_env). Throws EnvMapError with
// ErrorCode::database naming the map and the manifest when the file has changed since the build
// or can no longer be read.
EnvMap load_database_env(const Database& db);

}  // namespace brdfnav
