// What the builder reloads of a finished build: the merge of recorded shards (the settings, the
// map and the scene come from the shards, not the caller).
#include <brdfnav/precompute/database.h>

#include <brdfnav/navigator/database_format.h>

namespace brdfnav {

void merge_recorded_shards(const std::vector<std::filesystem::path>& shards,
                           const std::filesystem::path& out, int threads,
                           const PrecomputeObserver& observer) {
  if (shards.empty()) throw DatabaseError("precompute merge: no shard given");
  // The profile, environment and scene are the first shard's; merge_shards checks the others.
  const ShardOrigin origin = read_shard_origin(shards.front());
  PrecomputeRequest request{make_profile(origin.profile), out, false, threads, observer};
  request.profile.resolution = origin.resolution;
  const EnvMap env = load_recorded_env(origin.env_path, origin.env_pixel_sha1,
                                       (shards.front() / db::kShardFile).string());
  merge_shards(shards, request, env, Scene::load(origin.scene));
}

}  // namespace brdfnav
