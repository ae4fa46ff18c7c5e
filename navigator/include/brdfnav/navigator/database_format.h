// The on-disk layout of a database, the one definition its reader (database.cpp) and its writer
// (the builder's precompute_job.cpp) share: file names, the keys of the images' headers, the
// float32 table format and the YAML of the manifest, of an unfinished build's settings and of a
// shard.
#pragma once

#include <brdfnav/core/image.h>
#include <brdfnav/navigator/database.h>

#include <cstdint>
#include <filesystem>
#include <map>
#include <span>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace brdfnav::db {

inline constexpr const char* kManifestFile = "manifest.yaml";
// The settings of an unfinished build, in its work directory: a resumed build must match them.
inline constexpr const char* kSettingsFile = "settings.yaml";
// A shard's manifest: the settings, `shard: i/N` and the checksums of its images.
inline constexpr const char* kShardFile = "shard.yaml";
inline constexpr const char* kDiffuseFile = "diffuse.exr";
inline constexpr const char* kBasisFile = "embedding/basis.f32";
inline constexpr const char* kSingularValuesFile = "embedding/singular_values.f32";

// The keys of the images' headers are db::kHeader* (brdfnav/core/image.h).

std::string image_file(ModelId id, std::size_t node);
std::string coefficients_file(ModelId id);
std::string conversion_file(ModelId from, ModelId to);
// Every file of a database with these grids except the manifest, sorted.
std::vector<std::string> database_files(const std::vector<ProfileGrid>& grids);
// A model's blend check: one row per cell of its grid (ParamGrid::cell_index), one column, the
// metric's distance between the blend of the database's images (blend_images()) and an exact
// render at the cell's midpoint, for rho_d = 0 and rho_s = 1. The builder writes one per model;
// databases built before the check have none, and are still complete.
std::string blend_check_file(ModelId id);
// The files a database of these grids may hold beyond database_files(): the blend checks, sorted.
std::vector<std::string> optional_database_files(const std::vector<ProfileGrid>& grids);
// The columns of a conversion table into `to`: one row per node of the source grid, holding
// `to`'s parameters, scale RGB, relative error, image distance.
std::size_t conversion_columns(ModelId to);

// A row-major float32 matrix (see docs/DATABASE.md for the file layout).
struct Table {
  std::uint32_t rows = 0, cols = 0;
  std::vector<float> values;
  float at(std::size_t r, std::size_t c) const { return values[r * cols + c]; }
};
void write_table(const std::filesystem::path& path, const Table& table);
// A conversion into `to` as a table row of conversion_columns(to) floats, and back: the one
// place that knows where each field sits. std::invalid_argument when the sizes do not match.
void write_conversion_row(const Conversion& c, ModelId to, std::span<float> row);
Conversion read_conversion_row(std::span<const float> row, ModelId to);
// Throws DatabaseError naming the file when it is unreadable, malformed or not rows x cols.
Table read_table(const std::filesystem::path& path, std::uint32_t rows, std::uint32_t cols);
// The rows and columns a table's header declares (a table's values unread). Throws DatabaseError
// naming the file when it is unreadable or not a table.
std::pair<std::uint32_t, std::uint32_t> read_table_shape(const std::filesystem::path& path);

// One model's embedding coefficients (`components` x q nodes x grid nodes x 3), from the
// database or work directory `dir` of that format version. Since version 2 the file holds one row
// per column of the matrix, and is mapped rather than read: a process holds only the columns its
// queries touch. Version 1 held the matrix itself (one row per component), and is read whole.
// Throws DatabaseError naming the file.
ModelEmbedding read_model_embedding(const std::filesystem::path& dir,
                                    const std::vector<double>& q_nodes, int components,
                                    const ProfileGrid& grid, int format_version);
// The table of a model's embedding in the current format version: one row per column.
Table embedding_table(const ModelEmbedding& m);

// One value of the builder's options as the builder holds it: written as an integer or a double.
using SettingValue = std::variant<std::int64_t, std::uint64_t, double>;
// A flow map of the manifest (render_quality, pca, fit), its keys in the order written.
struct SettingsGroup {
  std::string name;
  std::vector<std::pair<std::string, SettingValue>> values;
};

// How a build was made, as plain values: everything the manifest holds but `components` and
// the checksums. The builder fills it from its profile, map and scene (build_settings()).
struct BuildSettings {
  std::string generator;  // "brdfnav VERSION"
  int renderer_revision = 0;
  std::string profile;
  int resolution = 0;
  std::string scene;  // the scene's description
  std::string env_path, env_pixel_sha1;
  int env_width = 0, env_height = 0;
  std::vector<double> q_nodes;
  std::vector<ProfileGrid> grids;
  std::vector<SettingsGroup> options;
};

using FileSums = std::map<std::string, std::string>;  // relative path -> SHA-1 (hex)

// What a build is asked to make: an unfinished build's settings.yaml, which a resumed build and
// every shard of one build must match byte for byte.
std::string settings_yaml(const BuildSettings& settings);
// The complete manifest.
std::string manifest_yaml(const BuildSettings& settings, int components, const FileSums& files);
// A shard's shard.yaml: the settings, `shard: i/N` and its images' checksums.
std::string shard_yaml(const BuildSettings& settings, int shard_index, int shard_count,
                       const FileSums& files);
// Throws DatabaseError naming the file and the key.
Manifest read_manifest(const std::filesystem::path& path);

}  // namespace brdfnav::db
