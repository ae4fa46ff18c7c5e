// What the builder reloads of a finished build: the environment map a database or a shard
// records, and the merge of recorded shards (the settings come from the shards, not the caller).
#include <brdfnav/precompute/database.h>

#include <brdfnav/navigator/database_format.h>

#include <optional>

namespace brdfnav {

namespace {

// The map at `path` with the pixels a build recorded (`pixel_sha1`), loaded as any build loaded
// it: a --sanitize-env build zeroed NaN/Inf texels, and a map that needed it could not have been
// built without. `recorder` names the file that records it, for the error.
EnvMap load_recorded_env(const std::string& path, const std::string& pixel_sha1,
                         const std::string& recorder) {
  std::optional<EnvMap> env;
  try {
    env = EnvMap::load(path, {.sanitize = true}, [](const std::string&) {});
  } catch (const EnvMapError& e) {
    throw DatabaseError(e.what() + (" (the environment map " + recorder + " names)"));
  }
  if (env->pixel_hash() != pixel_sha1)
    throw DatabaseError(path + ": changed since the database was built (pixel sha1 " +
                        env->pixel_hash() + ", " + recorder + " says " + pixel_sha1 + ")");
  return std::move(*env);
}

}  // namespace

EnvMap load_database_env(const Database& db) {
  const Manifest& m = db.manifest();
  return load_recorded_env(m.env_path, m.env_hash, (db.dir() / db::kManifestFile).string());
}

void merge_recorded_shards(const std::vector<std::filesystem::path>& shards,
                           const std::filesystem::path& out, int threads,
                           const PrecomputeObserver& observer) {
  if (shards.empty()) throw DatabaseError("precompute merge: no shard given");
  // The profile, environment and scene are the first shard's; merge_shards checks the others.
  const ShardOrigin origin = read_shard_origin(shards.front());
  PrecomputeRequest request{make_profile(origin.profile), out, false, threads, observer};
  request.profile.resolution = origin.resolution;
  const EnvMap env = load_recorded_env(origin.env_path, origin.env_hash,
                                       (shards.front() / db::kShardFile).string());
  merge_shards(shards, request, env, Scene::load(origin.scene));
}

}  // namespace brdfnav
