// The precomputed database (issue #4; format in docs/DATABASE.md): the pre-rendered images, the
// unified embedding and the model-to-model conversion tables, with a manifest that records how
// they were made and a SHA-1 of every file. precompute_database() builds one atomically and can
// resume an interrupted build; Database::open() verifies one and loads what navigation needs.
#pragma once

#include <brdfnav/precompute/embedding.h>
#include <brdfnav/precompute/env_map.h>
#include <brdfnav/precompute/profile.h>
#include <brdfnav/precompute/scene.h>

#include <filesystem>
#include <functional>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace brdfnav {

inline constexpr int kDatabaseFormatVersion = 1;

// A database that cannot be built or used; the message names the file.
class DatabaseError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Best fit of one grid node of model `from` by model `to` (fit_lobe), and how far apart the two
// are in the image metric (through the embedding; both with rho_d = 0).
struct Conversion {
  std::vector<double> params;  // of `to`, in model_info(to).params order
  Rgb scale;                   // rho_s of the fit for rho_s = 1 of the source
  double relative_error;       // BRDF-space, from fit_lobe
  double image_distance;       // embedded metric between the node material and its fit
};

struct ConversionTable {
  ModelId from, to;
  std::vector<Conversion> nodes;  // one per node of from's grid
};

// What the manifest says (everything but the build settings, which are only recorded).
struct Manifest {
  int format_version = kDatabaseFormatVersion;
  std::string profile;
  int resolution = 0;
  std::string scene;
  std::string env_path, env_hash;
  int components = 0;  // embedding coefficients per channel
  std::vector<double> q_nodes;
  std::vector<ProfileGrid> grids;
  std::map<std::string, std::string> files;  // path relative to the database -> SHA-1 (hex)
};

// Receives (phase, done, total) for progress bars and one line per event for the log.
struct PrecomputeObserver {
  std::function<void(const std::string& phase, std::size_t done, std::size_t total)> progress;
  std::function<void(const std::string& line)> log;
};

struct PrecomputeRequest {
  Profile profile;
  std::filesystem::path out;  // the database directory; must not exist yet
  bool resume = false;        // reuse the finished units in OUT.partial/
  int threads = 0;            // 0: every hardware thread
  PrecomputeObserver observer;
  // Render only the images whose unit index (diffuse 0, then every model's nodes in order) is
  // shard_index modulo shard_count, into OUT as a shard (shard.yaml instead of a manifest).
  int shard_index = 0, shard_count = 1;
};

// Renders, embeds and fits into OUT.partial/ (each unit written atomically), writes the manifest
// last and renames the directory to OUT. Without `resume` an existing OUT.partial/ is discarded;
// with it, finished units are verified and reused, and the result is byte-identical to an
// uninterrupted run. Throws DatabaseError (and the renderer's errors) naming the file.
void precompute_database(const PrecomputeRequest& request, const EnvMap& env, const Scene& scene);

// SHA-1 of a file's bytes in hex, as the manifest records it. Throws DatabaseError naming the file.
std::string file_sha1(const std::filesystem::path& path);

// Where a shard was made: enough to rebuild its profile, environment and scene for the merge.
struct ShardOrigin {
  std::string profile;
  int resolution = 0;
  std::string env_path, scene;
  int shard_index = 0, shard_count = 1;
  std::map<std::string, std::string> files;  // the shard's images -> SHA-1
};
// Reads SHARD/shard.yaml. Throws DatabaseError naming the file.
ShardOrigin read_shard_origin(const std::filesystem::path& shard);

// Joins the shards of one build (every i of `--shard i/N`, made with the same settings as
// `request`, which is checked) into request.out, then embeds and fits: the database is
// byte-identical to an unsharded build. Verifies every shard file's checksum.
void merge_shards(const std::vector<std::filesystem::path>& shards,
                  const PrecomputeRequest& request, const EnvMap& env, const Scene& scene);

class Database {
 public:
  // Checks the format version, every file's SHA-1, that every expected file is listed and that
  // the files belong together (image sizes and provenance, table shapes). Loads the embedding
  // and the conversion tables, not the images. Throws DatabaseError naming the file.
  static Database open(const std::filesystem::path& dir);

  const std::filesystem::path& dir() const { return dir_; }
  const Manifest& manifest() const { return manifest_; }
  // nullptr when the database does not hold the model.
  const ModelEmbedding* embedding(ModelId id) const;
  const ConversionTable* conversion(ModelId from, ModelId to) const;
  std::filesystem::path image_path(ModelId id, std::size_t node) const;
  std::filesystem::path diffuse_path() const;

 private:
  std::filesystem::path dir_;
  Manifest manifest_;
  std::vector<ModelEmbedding> embeddings_;
  std::vector<ConversionTable> conversions_;
};

// The environment map the database's images were rendered under, loaded from the manifest's path
// (NaN/Inf texels set to 0, as a --sanitize-env build did) and checked against the manifest's
// pixel SHA-1. Throws DatabaseError naming the map and the manifest when the file has changed
// since the build or can no longer be read.
EnvMap load_database_env(const Database& db);

}  // namespace brdfnav
