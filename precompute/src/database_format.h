// The on-disk pieces of a database shared by the writer (precompute_job.cpp) and the reader
// (database.cpp): file names, the float32 table format, checksums and the manifest's YAML.
#pragma once

#include <brdfnav/precompute/database.h>

#include <yaml-cpp/yaml.h>

#include <cstdint>
#include <filesystem>
#include <string>
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

std::string image_file(ModelId id, std::size_t node);
std::string coefficients_file(ModelId id);
std::string conversion_file(ModelId from, ModelId to);
// Every file of a database with these grids except the manifest, sorted.
std::vector<std::string> database_files(const std::vector<ProfileGrid>& grids);
// The models of a conversion table's columns: `to`'s parameters, scale RGB, relative error,
// image distance.
std::size_t conversion_columns(ModelId to);

// A row-major float32 matrix (see docs/DATABASE.md for the file layout).
struct Table {
  std::uint32_t rows = 0, cols = 0;
  std::vector<float> values;
  float at(std::size_t r, std::size_t c) const { return values[r * cols + c]; }
};
void write_table(const std::filesystem::path& path, const Table& table);
// Throws DatabaseError naming the file when it is unreadable, malformed or not rows x cols.
Table read_table(const std::filesystem::path& path, std::uint32_t rows, std::uint32_t cols);

// The manifest without `components` and `files`: what a build is asked to make.
std::string settings_yaml(const Profile& profile, const EnvMap& env, const Scene& scene);
// The complete manifest.
std::string manifest_yaml(const Profile& profile, const EnvMap& env, const Scene& scene,
                          int components, const std::map<std::string, std::string>& files);
// A required key of a YAML map, or a DatabaseError naming the file and the key.
YAML::Node require(const YAML::Node& map, const std::string& key, const std::string& file);
// Throws DatabaseError naming the file and the key.
Manifest read_manifest(const std::filesystem::path& path);

}  // namespace brdfnav::db
