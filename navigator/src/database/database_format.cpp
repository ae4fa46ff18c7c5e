#include <brdfnav/navigator/database_format.h>

#include "mapped_file.h"

#include <brdfnav/core/atomic_file.h>
#include <brdfnav/core/sha1.h>

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <bit>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <tuple>

namespace brdfnav::db {

static_assert(std::endian::native == std::endian::little,
              "the database tables are little-endian float32, written as in memory");

namespace {

constexpr char kTableMagic[8] = {'B', 'N', 'A', 'V', 'T', 'B', 'L', '1'};
constexpr std::size_t kTableHeaderBytes = 16;  // the magic, rows and columns (uint32)

std::string model_name(ModelId id) {
  return std::string(model_info(id).name);
}

struct EmitValue {
  YAML::Emitter& out;
  template <typename T>
  void operator()(T v) const {
    out << v;
  }
};

void emit_settings(YAML::Emitter& out, const BuildSettings& s) {
  out << YAML::Key << "brdfnav_database" << YAML::Value << kDatabaseFormatVersion;
  out << YAML::Key << "generator" << YAML::Value << s.generator;
  out << YAML::Key << "renderer_revision" << YAML::Value << s.renderer_revision;
  out << YAML::Key << "profile" << YAML::Value << s.profile;
  out << YAML::Key << "resolution" << YAML::Value << s.resolution;
  out << YAML::Key << "scene" << YAML::Value << s.scene;
  out << YAML::Key << "environment" << YAML::Value << YAML::BeginMap;
  out << YAML::Key << "path" << YAML::Value << s.env_path;
  out << YAML::Key << "pixel_sha1" << YAML::Value << s.env_pixel_sha1;
  out << YAML::Key << "width" << YAML::Value << s.env_width;
  out << YAML::Key << "height" << YAML::Value << s.env_height << YAML::EndMap;
  out << YAML::Key << "q_nodes" << YAML::Value << YAML::Flow << s.q_nodes;
  out << YAML::Key << "models" << YAML::Value << YAML::BeginMap;
  for (const ProfileGrid& g : s.grids) {
    out << YAML::Key << model_name(g.model) << YAML::Value << YAML::BeginMap;
    for (std::size_t d = 0; d < g.grid.dimensions(); ++d)
      out << YAML::Key << std::string(g.grid.specs()[d].name) << YAML::Value << YAML::Flow
          << g.grid.axis(d);
    out << YAML::EndMap;
  }
  out << YAML::EndMap;
  for (const SettingsGroup& group : s.options) {
    out << YAML::Key << group.name << YAML::Value << YAML::Flow << YAML::BeginMap;
    for (const auto& [key, value] : group.values) {
      out << YAML::Key << key << YAML::Value;
      std::visit(EmitValue{out}, value);
    }
    out << YAML::EndMap;
  }
}

YAML::Emitter& begin(YAML::Emitter& out) {
  out.SetDoublePrecision(17);  // round-trips every double exactly
  out << YAML::BeginMap;
  return out;
}

}  // namespace

namespace {
// A YAML file of the database, parsed; DatabaseError naming it when it cannot be read.
YAML::Node load_yaml(const std::string& file) {
  std::string text;
  try {
    text = read_file(file);
  } catch (const Error& e) {
    throw DatabaseError(e.what());
  }
  return YAML::Load(text);
}
}  // namespace

namespace {

// A required key of a manifest map, or a DatabaseError naming the file and the key.
YAML::Node require(const YAML::Node& map, const std::string& key, const std::string& file) {
  const YAML::Node node = map[key];
  if (!node) throw DatabaseError(file + ": missing key '" + key + "'");
  return node;
}

// The models' grids. Every node has an image the manifest lists, so a grid with more nodes than
// `listed` files is refused before anything sized by it is made (a few hundred numbers in a
// corrupt manifest would otherwise name billions of files).
std::vector<ProfileGrid> parse_grids(const YAML::Node& models, std::size_t listed,
                                     const std::string& file) {
  std::vector<ProfileGrid> grids;
  for (const ModelInfo& info : brdfnav::models()) {
    const YAML::Node m = models[std::string(info.name)];
    if (!m) continue;
    std::vector<std::vector<double>> axes;
    std::size_t nodes = 1;
    for (const ParamSpec& spec : info.params) {
      const std::string key = "models." + std::string(info.name) + "." + std::string(spec.name);
      const auto axis = require(m, std::string(spec.name), file).as<std::vector<double>>();
      if (axis.size() < 2) throw DatabaseError(file + ": " + key + " needs at least two nodes");
      for (std::size_t i = 0; i < axis.size(); ++i)
        if (!in_valid_range(spec, axis[i]) || (i > 0 && !(axis[i] > axis[i - 1])))
          throw DatabaseError(file + ": " + key +
                              " must increase strictly within the parameter's valid range");
      nodes *= axis.size();
      if (nodes > listed)
        throw DatabaseError(file + ": models." + std::string(info.name) +
                            " has more nodes than the manifest lists files");
      axes.push_back(axis);
    }
    grids.push_back({info.id, ParamGrid(info.params, std::move(axes))});
  }
  if (grids.empty()) throw DatabaseError(file + ": 'models' names no known model");
  return grids;
}

}  // namespace

std::string image_file(ModelId id, std::size_t node) {
  char name[32];
  std::snprintf(name, sizeof name, "%05zu.exr", node);
  return "images/" + model_name(id) + "/" + name;
}

std::string coefficients_file(ModelId id) {
  return "embedding/" + model_name(id) + ".f32";
}

std::string conversion_file(ModelId from, ModelId to) {
  return "conversions/" + model_name(from) + "_to_" + model_name(to) + ".f32";
}

std::size_t conversion_columns(ModelId to) {
  return model_info(to).params.size() + 5;
}

void write_conversion_row(const Conversion& c, ModelId to, std::span<float> row) {
  const std::size_t dims = model_info(to).params.size();
  if (row.size() != conversion_columns(to) || c.params.size() != dims)
    throw std::invalid_argument("conversion row: " + std::to_string(c.params.size()) +
                                " parameters in a row of " + std::to_string(row.size()));
  for (std::size_t i = 0; i < dims; ++i) row[i] = float(c.params[i]);
  for (int k = 0; k < 3; ++k) row[dims + k] = float(c.scale[k]);
  row[dims + 3] = float(c.relative_error);
  row[dims + 4] = float(c.image_distance);
}

Conversion read_conversion_row(std::span<const float> row, ModelId to) {
  const std::size_t dims = model_info(to).params.size();
  if (row.size() != conversion_columns(to))
    throw std::invalid_argument("conversion row of " + std::to_string(row.size()) +
                                " values for a model of " + std::to_string(dims) + " parameters");
  Conversion c;
  c.params.assign(row.begin(), row.begin() + dims);
  c.scale = Rgb(row[dims], row[dims + 1], row[dims + 2]);
  c.relative_error = row[dims + 3];
  c.image_distance = row[dims + 4];
  return c;
}

std::vector<std::string> database_files(const std::vector<ProfileGrid>& grids) {
  std::vector<std::string> files{kDiffuseFile, kBasisFile, kSingularValuesFile};
  for (const ProfileGrid& a : grids) {
    for (std::size_t n = 0; n < a.grid.node_count(); ++n) files.push_back(image_file(a.model, n));
    files.push_back(coefficients_file(a.model));
    for (const ProfileGrid& b : grids)
      if (b.model != a.model) files.push_back(conversion_file(a.model, b.model));
  }
  std::sort(files.begin(), files.end());
  return files;
}

std::string blend_check_file(ModelId id) {
  return "previews/" + model_name(id) + ".f32";
}

std::vector<std::string> optional_database_files(const std::vector<ProfileGrid>& grids) {
  std::vector<std::string> files;
  for (const ProfileGrid& g : grids) files.push_back(blend_check_file(g.model));
  std::sort(files.begin(), files.end());
  return files;
}

void write_table(const std::filesystem::path& path, const Table& table) {
  std::string bytes(kTableMagic, sizeof kTableMagic);
  bytes.append(reinterpret_cast<const char*>(&table.rows), 4);
  bytes.append(reinterpret_cast<const char*>(&table.cols), 4);
  bytes.append(reinterpret_cast<const char*>(table.values.data()), table.values.size() * 4);
  write_file_atomic(path, bytes);
}

namespace {
// The magic and the shape of a table whose stream is at its start.
std::pair<std::uint32_t, std::uint32_t> read_header(std::istream& in,
                                                    const std::filesystem::path& path) {
  char magic[8];
  std::uint32_t rows = 0, cols = 0;
  in.read(magic, 8);
  in.read(reinterpret_cast<char*>(&rows), 4);
  in.read(reinterpret_cast<char*>(&cols), 4);
  if (!in || std::memcmp(magic, kTableMagic, 8) != 0)
    throw DatabaseError(path.string() + ": not a brdfnav table (bad header)");
  return {rows, cols};
}

void check_shape(const std::filesystem::path& path, std::uint32_t rows, std::uint32_t cols,
                 std::uint32_t expected_rows, std::uint32_t expected_cols) {
  if (rows != expected_rows || cols != expected_cols)
    throw DatabaseError(path.string() + ": table is " + std::to_string(rows) + " x " +
                        std::to_string(cols) + ", the manifest implies " +
                        std::to_string(expected_rows) + " x " + std::to_string(expected_cols));
}
}  // namespace

Table read_table(const std::filesystem::path& path, std::uint32_t rows, std::uint32_t cols) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw DatabaseError(path.string() + ": cannot open");
  Table t;
  std::tie(t.rows, t.cols) = read_header(in, path);
  check_shape(path, t.rows, t.cols, rows, cols);
  t.values.resize(std::size_t(rows) * cols);
  in.read(reinterpret_cast<char*>(t.values.data()), std::streamsize(t.values.size() * 4));
  if (!in || in.peek() != std::char_traits<char>::eof())
    throw DatabaseError(path.string() + ": table size does not match its header");
  return t;
}

std::pair<std::uint32_t, std::uint32_t> read_table_shape(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw DatabaseError(path.string() + ": cannot open");
  return read_header(in, path);
}

ModelEmbedding read_model_embedding(const std::filesystem::path& dir,
                                    const std::vector<double>& q_nodes, int components,
                                    const ProfileGrid& g, int format_version) {
  const auto columns = std::uint32_t(q_nodes.size() * g.grid.node_count() * 3);
  const auto k = std::uint32_t(components);
  const std::filesystem::path path = dir / coefficients_file(g.model);
  if (format_version < 2) {  // k x columns: a column's coefficients are strided; read and transpose
    const Table t = read_table(path, k, columns);
    Eigen::MatrixXf c(t.rows, t.cols);
    for (std::uint32_t i = 0; i < t.rows; ++i)
      for (std::uint32_t j = 0; j < t.cols; ++j) c(i, j) = t.at(i, j);
    return ModelEmbedding(g.model, g.grid, q_nodes, std::move(c));
  }
  // One row per column: the file is the column-major k x columns matrix, mapped as it lies.
  auto file = std::make_shared<const MappedFile>(path);
  const std::span<const std::byte> bytes = file->bytes();
  std::istringstream header(std::string(reinterpret_cast<const char*>(bytes.data()),
                                        std::min<std::size_t>(bytes.size(), kTableHeaderBytes)));
  const auto [rows, cols] = read_header(header, path);
  check_shape(path, rows, cols, columns, k);
  if (bytes.size() != kTableHeaderBytes + std::size_t(rows) * cols * 4)
    throw DatabaseError(path.string() + ": table size does not match its header");
  const auto* values = reinterpret_cast<const float*>(bytes.data() + kTableHeaderBytes);
  return ModelEmbedding(g.model, g.grid, q_nodes, file,
                        ModelEmbedding::Coefficients(values, k, columns));
}

Table embedding_table(const ModelEmbedding& m) {
  const ModelEmbedding::Coefficients& c = m.coefficients();
  return {std::uint32_t(c.cols()), std::uint32_t(c.rows()),
          std::vector<float>(c.data(), c.data() + c.size())};
}

std::string settings_yaml(const BuildSettings& settings) {
  YAML::Emitter out;
  emit_settings(begin(out), settings);
  out << YAML::EndMap;
  return std::string(out.c_str()) + "\n";
}

std::string manifest_yaml(const BuildSettings& settings, int components, const FileSums& files) {
  YAML::Emitter out;
  emit_settings(begin(out), settings);
  out << YAML::Key << "components" << YAML::Value << components;
  out << YAML::Key << "files" << YAML::Value << YAML::BeginMap;
  for (const auto& [name, sha] : files) out << YAML::Key << name << YAML::Value << sha;
  out << YAML::EndMap << YAML::EndMap;
  return std::string(out.c_str()) + "\n";
}

// The settings' text, then the shard's own keys: a merge checks that every shard's file starts
// with the same settings.
std::string shard_yaml(const BuildSettings& settings, int shard_index, int shard_count,
                       const FileSums& files) {
  std::string text = settings_yaml(settings);
  text +=
      "shard: " + std::to_string(shard_index) + "/" + std::to_string(shard_count) + "\nfiles:\n";
  for (const auto& [name, sha] : files) text += "  " + name + ": " + sha + "\n";
  return text;
}

Manifest read_manifest(const std::filesystem::path& path) {
  const std::string file = path.string();
  if (!std::filesystem::exists(path))
    throw DatabaseError(file + ": no such file (not a brdfnav database, or an unfinished one)");
  try {
    const YAML::Node root = load_yaml(file);
    Manifest m;
    m.format_version = require(root, "brdfnav_database", file).as<int>();
    if (m.format_version < kOldestDatabaseFormatVersion ||
        m.format_version > kDatabaseFormatVersion)
      throw DatabaseError(file + ": database format version " + std::to_string(m.format_version) +
                          "; this brdfnav reads versions " +
                          std::to_string(kOldestDatabaseFormatVersion) + " to " +
                          std::to_string(kDatabaseFormatVersion));
    m.profile = require(root, "profile", file).as<std::string>();
    m.resolution = require(root, "resolution", file).as<int>();
    m.scene = require(root, "scene", file).as<std::string>();
    const YAML::Node env = require(root, "environment", file);
    m.env_path = require(env, "path", file).as<std::string>();
    m.env_pixel_sha1 = require(env, "pixel_sha1", file).as<std::string>();
    m.components = require(root, "components", file).as<int>();
    if (m.components < 1) throw DatabaseError(file + ": components must be positive");
    m.q_nodes = require(root, "q_nodes", file).as<std::vector<double>>();
    // The embedding interpolates between q nodes: at least two, increasing from 0 to 1.
    const auto not_increasing = [](double a, double b) { return !(b > a); };
    if (m.q_nodes.size() < 2 || m.q_nodes.front() != 0 || m.q_nodes.back() != 1 ||
        std::adjacent_find(m.q_nodes.begin(), m.q_nodes.end(), not_increasing) != m.q_nodes.end())
      throw DatabaseError(file + ": q_nodes must increase strictly from 0 to 1");
    m.files = require(root, "files", file).as<std::map<std::string, std::string>>();
    m.grids = parse_grids(require(root, "models", file), m.files.size(), file);
    if (const YAML::Node quality = root["render_quality"]) {
      if (!quality.IsMap()) throw DatabaseError(file + ": 'render_quality' is not a map");
      for (const auto& knob : quality)
        m.render_quality.emplace_back(knob.first.as<std::string>(), knob.second.as<double>());
    }
    return m;
  } catch (const YAML::Exception& e) {
    throw DatabaseError(file + ": line " + std::to_string(e.mark.line + 1) + ": " + e.msg);
  }
}

}  // namespace brdfnav::db

namespace brdfnav {

ShardOrigin read_shard_origin(const std::filesystem::path& shard) {
  const std::string file = (shard / db::kShardFile).string();
  if (!std::filesystem::exists(file))
    throw DatabaseError(file + ": no such file (not a finished brdfnav shard)");
  try {
    const YAML::Node root = db::load_yaml(file);
    ShardOrigin o;
    o.profile = db::require(root, "profile", file).as<std::string>();
    o.resolution = db::require(root, "resolution", file).as<int>();
    const YAML::Node env = db::require(root, "environment", file);
    o.env_path = db::require(env, "path", file).as<std::string>();
    o.env_pixel_sha1 = db::require(env, "pixel_sha1", file).as<std::string>();
    o.scene = db::require(root, "scene", file).as<std::string>();
    const std::string shard_text = db::require(root, "shard", file).as<std::string>();
    if (std::sscanf(shard_text.c_str(), "%d/%d", &o.shard_index, &o.shard_count) != 2 ||
        o.shard_count < 1 || o.shard_index < 0 || o.shard_index >= o.shard_count)
      throw DatabaseError(file + ": 'shard' is '" + shard_text + "', expected i/N with 0 <= i < N");
    o.files = db::require(root, "files", file).as<std::map<std::string, std::string>>();
    return o;
  } catch (const YAML::Exception& e) {
    throw DatabaseError(file + ": line " + std::to_string(e.mark.line + 1) + ": " + e.msg);
  }
}

std::string file_sha1(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw DatabaseError(path.string() + ": missing or unreadable");
  Sha1 sha;
  std::vector<char> buffer(1 << 20);
  while (in) {
    in.read(buffer.data(), std::streamsize(buffer.size()));
    sha.append(buffer.data(), static_cast<std::size_t>(in.gcount()));
  }
  if (in.bad()) throw DatabaseError(path.string() + ": read error");
  return sha.digest();
}

}  // namespace brdfnav
