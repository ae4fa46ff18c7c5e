#include <brdfnav/lookdev/database_env.h>

#include <brdfnav/navigator/database_format.h>

namespace brdfnav {

EnvMap load_database_env(const Database& db) {
  const Manifest& m = db.manifest();
  return load_recorded_env(m.env_path, m.env_pixel_sha1, (db.dir() / db::kManifestFile).string());
}

}  // namespace brdfnav
