// The database builder (format in docs/DATABASE.md): precompute_database() renders, embeds and
// fits a database atomically and can resume an interrupted build; shards of one build are
// rendered apart and merged. What reads a database is brdfnav/navigator/database.h.
#pragma once

#include <brdfnav/core/progress.h>
#include <brdfnav/navigator/database.h>
#include <brdfnav/precompute/embedding.h>
#include <brdfnav/precompute/profile.h>
#include <brdfnav/renderer/env_map.h>
#include <brdfnav/renderer/scene.h>

#include <filesystem>
#include <functional>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace brdfnav {

// Receives the build's progress (phases "render", "cells", "load images", "embedding", "fits",
// "blend check", "checksums") and one line per event for the log.
struct PrecomputeObserver {
  ProgressSink progress;
  std::function<void(const std::string& line)> log;
};

struct PrecomputeRequest {
  Profile profile;
  std::filesystem::path out;  // the database directory; must not exist yet
  bool resume = false;        // reuse the finished units in OUT.partial/
  int threads = 0;            // 0: every hardware thread
  PrecomputeObserver observer;
  // Render only the units whose index is shard_index modulo shard_count (diffuse 0, then every
  // model's node units in order, then every model's cell groups, whose midpoints the merge's blend
  // check measures), into OUT as a shard (shard.yaml instead of a manifest).
  int shard_index = 0, shard_count = 1;
};

// Renders, embeds and fits into OUT.partial/ (each unit written atomically), writes the manifest
// last and renames the directory to OUT. Without `resume` an existing OUT.partial/ is discarded;
// with it, finished units are verified and reused, and the result is byte-identical to an
// uninterrupted run. Throws DatabaseError (and the renderer's errors) naming the file.
void precompute_database(const PrecomputeRequest& request, const EnvMap& env, const Scene& scene);

// Joins the shards of one build (every i of `--shard i/N`, made with the same settings as
// `request`, which is checked) into request.out, then embeds, fits and runs the blend check from
// the midpoints the shards rendered (rendering any a shard lacks): the database is byte-identical
// to an unsharded build. Verifies every shard file's checksum; refuses a shard naming a file
// outside itself.
void merge_shards(const std::vector<std::filesystem::path>& shards,
                  const PrecomputeRequest& request, const EnvMap& env, const Scene& scene);

// merge_shards() with the settings the shards recorded: the first shard's profile, resolution,
// scene and environment map (loaded as the build loaded it, and checked against its pixel SHA-1).
void merge_recorded_shards(const std::vector<std::filesystem::path>& shards,
                           const std::filesystem::path& out, int threads,
                           const PrecomputeObserver& observer);

}  // namespace brdfnav
