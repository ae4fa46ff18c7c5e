// Database::open(): verification of a database directory and loading of its tables.
#include <brdfnav/navigator/database_format.h>

#include <brdfnav/core/image.h>
#include <brdfnav/core/material.h>
#include <brdfnav/navigator/image_input.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

namespace brdfnav {

namespace fs = std::filesystem;

namespace {

// The manifest lists exactly the files the grids imply, and each exists with its checksum. Only
// those: a listed name such as /dev/zero or ../../x would send the checksum outside the database
// (or read forever).
void check_files(const fs::path& dir, const Manifest& m) {
  const std::string manifest = (dir / db::kManifestFile).string();
  const std::vector<std::string> required = db::database_files(m.grids),
                                 optional = db::optional_database_files(m.grids);
  for (const std::string& f : required)
    if (!m.files.contains(f)) throw DatabaseError(manifest + ": does not list the file " + f);
  for (const auto& [name, sha] : m.files)
    if (!std::binary_search(required.begin(), required.end(), name) &&
        !std::binary_search(optional.begin(), optional.end(), name))
      throw DatabaseError(manifest + ": lists the file " + name +
                          ", which is not part of a database of its grids");
  for (const auto& [name, sha] : m.files) {
    const fs::path path = dir / name;
    if (!fs::exists(path)) throw DatabaseError(path.string() + ": missing");
    if (file_sha1(path) != sha)
      throw DatabaseError(path.string() +
                          ": checksum mismatch (the file is corrupt or from another database)");
  }
}

// A grid image was rendered at its node: the parameters in its header's material are the
// manifest's grid values. The manifest has no checksum of its own, so without this an edited grid
// value would move every query and conversion silently.
void check_node(const ImageHeader& image, const std::string& file, const ProfileGrid& g,
                std::size_t node) {
  const std::string header = image.attribute(db::kHeaderMaterial);
  Material rendered;
  try {
    rendered = parse_material_spec(header);
  } catch (const MaterialError& e) {
    throw DatabaseError(file + ": its header's material '" + header +
                        "' is unreadable: " + e.what());
  }
  if (rendered.model != g.model)
    throw DatabaseError(file + ": rendered with model '" + header + "', the manifest's grid is " +
                        std::string(model_info(g.model).name) + "'s");
  const std::vector<double> values = g.grid.node_values(node);
  for (std::size_t d = 0; d < values.size(); ++d)
    if (rendered.params[d] != values[d]) {
      char text[160];
      std::snprintf(text, sizeof text, ": rendered at %s = %.17g, the manifest's grid says %.17g",
                    std::string(g.grid.specs()[d].name).c_str(), rendered.params[d], values[d]);
      throw DatabaseError(file + text);
    }
}

// An image belongs to the database when its size, its mask and the environment, scene and
// resolution in its header are the manifest's (and, for a grid image, its node's parameters).
void check_image(const fs::path& path, const Manifest& m, const Image& diffuse,
                 const ProfileGrid* grid = nullptr, std::size_t node = 0) {
  const std::string file = path.string();
  ImageHeader header;
  try {
    header = read_image_header(path);
  } catch (const ImageError& e) {
    throw DatabaseError(e.what());
  }
  if (header.width != m.resolution || header.height != m.resolution)
    throw DatabaseError(file + ": image is " + std::to_string(header.width) + "x" +
                        std::to_string(header.height) + ", the manifest says " +
                        std::to_string(m.resolution));
  if (header.attribute(db::kHeaderEnvSha1) != m.env_pixel_sha1)
    throw DatabaseError(file + ": rendered under another environment map (pixel SHA-1 " +
                        header.attribute(db::kHeaderEnvSha1) + ", the manifest says " +
                        m.env_pixel_sha1 + ")");
  if (header.attribute(db::kHeaderScene) != m.scene)
    throw DatabaseError(file + ": rendered with scene '" + header.attribute(db::kHeaderScene) +
                        "', the manifest says '" + m.scene + "'");
  if (grid) check_node(header, file, *grid, node);
  if (diffuse.rgba.empty()) return;
  const Image image = read_image(path);
  for (std::size_t i = 3; i < image.rgba.size(); i += 4)
    if ((image.rgba[i] > 0.5f) != (diffuse.rgba[i] > 0.5f))
      throw DatabaseError(file + ": its mask (alpha) differs from diffuse.exr's");
}

ConversionTable load_conversion(const fs::path& dir, const ProfileGrid& a, ModelId to) {
  const std::size_t cols = db::conversion_columns(to);
  const db::Table t = db::read_table(dir / db::conversion_file(a.model, to),
                                     std::uint32_t(a.grid.node_count()), std::uint32_t(cols));
  ConversionTable table{a.model, to, {}};
  for (std::size_t n = 0; n < t.rows; ++n)
    table.nodes.push_back(db::read_conversion_row({&t.values[n * cols], cols}, to));
  return table;
}

// A model's blend check, when the manifest lists one: a distance per cell of its grid.
std::optional<std::vector<float>> load_blend_check(const fs::path& dir, const Manifest& m,
                                                   const ProfileGrid& g) {
  const std::string name = db::blend_check_file(g.model);
  if (!m.files.contains(name)) return std::nullopt;
  // Measured with another spline than the blend the thumbnails now show: it vouches for nothing.
  if (!blend_checks_current(m)) return std::nullopt;
  const db::Table t = db::read_table(dir / name, std::uint32_t(g.grid.cell_count()), 1);
  for (std::size_t c = 0; c < t.values.size(); ++c)
    if (!std::isfinite(t.values[c]) || t.values[c] < 0)
      throw DatabaseError((dir / name).string() + ": cell " + std::to_string(c) +
                          " holds a distance of " + std::to_string(t.values[c]) +
                          ", not a finite value >= 0");
  return t.values;
}

std::size_t covered_count(const Image& image) {
  std::size_t n = 0;
  for (std::size_t i = 3; i < image.rgba.size(); i += 4) n += image.rgba[i] > 0.5f;
  return n;
}

}  // namespace

Database Database::open(const fs::path& dir) {
  Database db;
  db.dir_ = dir;
  db.manifest_ = db::read_manifest(dir / db::kManifestFile);
  db.manifest_sha1_ = file_sha1(dir / db::kManifestFile);
  const Manifest& m = db.manifest_;
  check_files(dir, m);
  check_image(dir / db::kDiffuseFile, m, Image());
  const Image diffuse = read_image(dir / db::kDiffuseFile);
  for (const ProfileGrid& g : m.grids)
    for (std::size_t n = 0; n < g.grid.node_count(); ++n)
      check_image(dir / db::image_file(g.model, n), m, diffuse, &g, n);
  const auto k = std::uint32_t(m.components);
  db::read_table(dir / db::kSingularValuesFile, 1, k);
  db::read_table(dir / db::kBasisFile, std::uint32_t(covered_count(diffuse)), k);
  for (const ProfileGrid& a : m.grids) {
    db.embeddings_.push_back(
        db::read_model_embedding(dir, m.q_nodes, m.components, a, m.format_version));
    if (auto check = load_blend_check(dir, m, a)) db.blend_errors_[a.model] = std::move(*check);
    for (const ProfileGrid& b : m.grids)
      if (b.model != a.model) db.conversions_.push_back(load_conversion(dir, a, b.model));
  }
  return db;
}

const ModelEmbedding* Database::embedding(ModelId id) const {
  for (const ModelEmbedding& e : embeddings_)
    if (e.model() == id) return &e;
  return nullptr;
}

const ConversionTable* Database::conversion(ModelId from, ModelId to) const {
  for (const ConversionTable& t : conversions_)
    if (t.from == from && t.to == to) return &t;
  return nullptr;
}

std::optional<double> Database::blend_error(const Material& m) const {
  const auto it = blend_errors_.find(m.model);
  const ModelEmbedding* e = embedding(m.model);
  // A material of another shape is no cell's: the caller's validate() says what is wrong.
  if (it == blend_errors_.end() || !e || m.params.size() != e->grid().dimensions())
    return std::nullopt;
  // Nor is one beyond the grid: its blend is that of the grid's edge, not of the material.
  const ParamGrid& grid = e->grid();
  for (std::size_t d = 0; d < grid.dimensions(); ++d)
    if (!(m.params[d] >= grid.axis(d).front() && m.params[d] <= grid.axis(d).back()))
      return std::nullopt;
  // On a node in every parameter the blend is that node's image: the database's own render, which
  // the cell's check (at its midpoint) says nothing about.
  bool on_node = true;
  for (std::size_t d = 0; d < grid.dimensions() && on_node; ++d) {
    const double c = grid.grid_coordinate(d, m.params[d]);
    on_node = std::abs(c - std::round(c)) < kOnNode;
  }
  if (on_node) return 0.0;
  return it->second[grid.cell_index(m.params)];
}

std::span<const float> Database::blend_checks(ModelId id) const {
  const auto it = blend_errors_.find(id);
  return it == blend_errors_.end() ? std::span<const float>() : std::span<const float>(it->second);
}

fs::path Database::image_path(ModelId id, std::size_t node) const {
  return dir_ / db::image_file(id, node);
}

fs::path Database::diffuse_path() const {
  return dir_ / db::kDiffuseFile;
}

}  // namespace brdfnav
