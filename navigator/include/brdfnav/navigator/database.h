// The precomputed database, read side (format in docs/DATABASE.md): the pre-rendered images, the
// unified embedding and the model-to-model conversion tables, with a manifest that records how
// they were made and a SHA-1 of every file. Database::open() verifies one and loads what
// navigation needs; nothing here renders or builds (the builder, brdfnav/precompute/database.h,
// writes databases through database_format.h beside this file).
#pragma once

#include <brdfnav/core/error.h>
#include <brdfnav/core/grid.h>
#include <brdfnav/core/material.h>
#include <brdfnav/core/models.h>
#include <brdfnav/navigator/embedding.h>

#include <filesystem>
#include <map>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace brdfnav {

// The format version the builder writes, and the oldest the reader opens. Version 2 stores the
// embedding one column per row (database_format.h, read_model_embedding()). Version 3 has the
// same files, its blend check measured with ParamGrid::cubic_corners' spline as it now is (slopes
// that follow graded nodes, quadratic ends, one-sided at a kink); an earlier database's check
// was measured with Catmull-Rom in grid coordinates, and the reader ignores it.
inline constexpr int kDatabaseFormatVersion = 3;
inline constexpr int kOldestDatabaseFormatVersion = 1;
inline constexpr int kOldestBlendCheckFormatVersion = 3;

// A database that cannot be built or used; the message names the file.
using DatabaseError = LayerError<struct DatabaseErrorTag, ErrorCode::database>;

// One model's grid in a database (and in a profile, which the builder makes them from).
struct ProfileGrid {
  ModelId model;
  ParamGrid grid;
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
  std::string env_path, env_pixel_sha1;
  int components = 0;  // embedding coefficients per channel
  std::vector<double> q_nodes;
  std::vector<ProfileGrid> grids;
  std::map<std::string, std::string> files;  // path relative to the database -> SHA-1 (hex)
  // The render quality its images were made at, knob by knob as the builder recorded them
  // (brdfnav/renderer/render.h, kQualityKnobs and quality_from_record()).
  std::vector<std::pair<std::string, double>> render_quality;
};

// Whether the database's blend checks were measured with the spline the blend now uses (format
// version kOldestBlendCheckFormatVersion on); earlier ones describe another blend.
inline bool blend_checks_current(const Manifest& m) {
  return m.format_version >= kOldestBlendCheckFormatVersion;
}

// SHA-1 of a file's bytes in hex, as the manifest records it. Throws DatabaseError naming the file.
std::string file_sha1(const std::filesystem::path& path);

// Where a shard was made: enough to rebuild its profile, environment and scene for the merge.
struct ShardOrigin {
  std::string profile;
  int resolution = 0;
  std::string env_path, env_pixel_sha1, scene;
  int shard_index = 0, shard_count = 1;
  std::map<std::string, std::string> files;  // the shard's images -> SHA-1
};
// Reads SHARD/shard.yaml. Throws DatabaseError naming the file.
ShardOrigin read_shard_origin(const std::filesystem::path& shard);

class Database {
 public:
  // Checks the format version, every file's SHA-1, that every expected file is listed and that
  // the files belong together (image sizes and provenance, table shapes). Loads the embedding
  // and the conversion tables, not the images. Throws DatabaseError naming the file.
  static Database open(const std::filesystem::path& dir);

  const std::filesystem::path& dir() const { return dir_; }
  const Manifest& manifest() const { return manifest_; }
  // SHA-1 of manifest.yaml as it was read by open(): the provenance the CLI's and the server's
  // answers quote, computed once.
  const std::string& manifest_sha1() const { return manifest_sha1_; }
  // nullptr when the database does not hold the model.
  const ModelEmbedding* embedding(ModelId id) const;
  const ConversionTable* conversion(ModelId from, ModelId to) const;
  std::filesystem::path image_path(ModelId id, std::size_t node) const;
  std::filesystem::path diffuse_path() const;
  // The blend check of the grid cell holding `m`'s parameters (db::blend_check_file()): the image
  // metric's distance between the thumbnails' blend and an exact render at the cell's midpoint,
  // for the lobe alone (rho_d = 0, rho_s = 1: the hardest case for the cube root). nullopt when
  // the database holds no check for the model (built before the check), or the material is not
  // inside the grid (its blend would be the grid edge's). 0 for a material on a node in every
  // parameter (within kOnNode of it in grid coordinates), whose blend is that node's image.
  std::optional<double> blend_error(const Material& m) const;
  static constexpr double kOnNode = 1e-9;
  // Every cell's blend check of a model (ParamGrid::cell_index order); empty when it has none.
  std::span<const float> blend_checks(ModelId id) const;

 private:
  std::filesystem::path dir_;
  Manifest manifest_;
  std::string manifest_sha1_;
  std::vector<ModelEmbedding> embeddings_;
  std::vector<ConversionTable> conversions_;
  std::map<ModelId, std::vector<float>> blend_errors_;  // per cell, of the models that have one
};

}  // namespace brdfnav
