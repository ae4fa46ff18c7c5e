#include <brdfnav/io/material_yaml.h>

#include <brdfnav/core/atomic_file.h>

#include <yaml-cpp/eventhandler.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>
#include <vector>

namespace brdfnav {

namespace {

constexpr std::array<std::string_view, 6> kTopLevelKeys{
    "brdfnav_material", "model", "params", "rho_d", "rho_s", "colorspace"};
// What `brdfnav export` adds beside the material; a material reader skips them.
constexpr std::array<std::string_view, 2> kExportKeys{"provenance", "equivalents"};

std::string join(const std::vector<std::string_view>& names) {
  std::string out;
  for (std::string_view n : names) out += (out.empty() ? "" : ", ") + std::string(n);
  return out;
}

// "SOURCE:LINE: " with a 1-based line; nodes built in memory have no position, only the source.
std::string location(std::string_view source, const YAML::Mark& mark) {
  std::string out(source);
  if (!mark.is_null()) out += ":" + std::to_string(mark.line + 1);
  return out + ": ";
}

[[noreturn]] void fail(std::string_view source, const YAML::Mark& mark, std::string_view key,
                       std::string_view what) {
  throw MaterialError(location(source, mark) + std::string(key) + ": " + std::string(what));
}

std::string describe(const YAML::Node& node) {
  switch (node.Type()) {
    case YAML::NodeType::Map:
      return "a mapping";
    case YAML::NodeType::Sequence:
      return "a list";
    case YAML::NodeType::Scalar:
      return "'" + node.Scalar() + "'";
    default:
      return "nothing";
  }
}

// One key of a mapping. Errors about the whole value point at the key's line, which is where a
// reader looks even when the value starts on the next line (a block list).
struct Entry {
  std::string name;  // as written in the file
  std::string key;   // for messages: "rho_d", "params.alpha_x"
  YAML::Node key_node, value;
  YAML::Mark line() const { return key_node.Mark(); }
};

// The keys of one YAML mapping, rejecting non-scalar, duplicate and unknown keys on the way in.
class Mapping {
 public:
  // `name` is empty for the material mapping itself, "params" for the nested one; missing keys
  // are reported at `missing_at` (the line of the mapping's own key, if it has one).
  Mapping(const YAML::Node& node, std::string_view source, std::string_view name,
          std::vector<std::string_view> allowed, const YAML::Mark& missing_at)
      : source_(source),
        label_(name.empty() ? "material" : name),
        prefix_(name.empty() ? "" : std::string(name) + "."),
        mark_(missing_at) {
    for (const auto& kv : node) {
      if (!kv.first.IsScalar())
        fail(source_, kv.first.Mark(), label_, "keys must be names, got " + describe(kv.first));
      const std::string& key = kv.first.Scalar();
      if (const Entry* first = find(key))
        fail(source_, kv.first.Mark(), prefix_ + key,
             "duplicate key (first given on line " + std::to_string(first->line().line + 1) + ")");
      if (std::find(allowed.begin(), allowed.end(), key) == allowed.end())
        fail(source_, kv.first.Mark(), prefix_ + key,
             "unknown key (expected one of: " + join(allowed) + ")");
      entries_.push_back({key, prefix_ + key, kv.first, kv.second});
    }
  }

  const Entry* find(std::string_view name) const {
    for (const Entry& e : entries_)
      if (e.name == name) return &e;
    return nullptr;
  }
  const Entry* find_key(std::string_view key) const {
    for (const Entry& e : entries_)
      if (e.key == key) return &e;
    return nullptr;
  }
  const Entry& require(std::string_view name) const {
    if (const Entry* e = find(name)) return *e;
    missing(name);
  }
  [[noreturn]] void missing(std::string_view name) const {
    fail(source_, mark_, prefix_ + std::string(name), "missing");
  }
  const YAML::Mark& mark() const { return mark_; }

 private:
  std::string_view source_;
  std::string label_, prefix_;
  YAML::Mark mark_;
  std::vector<Entry> entries_;
};

// YAML's spellings of infinity and NaN (.inf, -.inf, .nan in any case), else a decimal number.
// from_chars is exact (round trip) and ignores the locale, unlike yaml-cpp's stream conversion.
std::optional<double> parse_float(std::string_view text) {
  const bool negative = text.starts_with('-');
  if (negative || text.starts_with('+')) text.remove_prefix(1);
  std::string lower(text);
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (lower == ".inf")
    return negative ? -std::numeric_limits<double>::infinity()
                    : std::numeric_limits<double>::infinity();
  if (lower == ".nan") return std::numeric_limits<double>::quiet_NaN();
  if (text.empty() || text.front() == '+' || text.front() == '-') return std::nullopt;
  double value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return negative ? -value : value;
}

// A finite number written as a plain scalar; a quoted "0.5" is a string, not a number.
double read_number(const YAML::Node& value, const YAML::Mark& at, std::string_view source,
                   std::string_view key) {
  if (!value.IsScalar()) fail(source, at, key, "expected a number, got " + describe(value));
  if (value.Tag() == "!" || value.Tag() == "tag:yaml.org,2002:str")
    fail(source, at, key, "expected a number, got the string \"" + value.Scalar() + "\"");
  const std::optional<double> number = parse_float(value.Scalar());
  if (!number) fail(source, at, key, "expected a number, got " + describe(value));
  if (!std::isfinite(*number)) fail(source, at, key, "must be finite, got " + value.Scalar());
  return *number;
}

std::string read_string(const Entry& e, std::string_view source) {
  if (!e.value.IsScalar())
    fail(source, e.line(), e.key, "expected a name, got " + describe(e.value));
  return e.value.Scalar();
}

void check_schema_version(const Entry& e, std::string_view source) {
  const std::string text = e.value.IsScalar() ? e.value.Scalar() : "";
  int version = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), version);
  if (text.empty() || ec != std::errc() || end != text.data() + text.size())
    fail(source, e.line(), e.key,
         "expected the schema version " + std::to_string(kMaterialSchemaVersion) + ", got " +
             describe(e.value));
  if (version != kMaterialSchemaVersion)
    fail(source, e.line(), e.key,
         "unsupported schema version " + text + " (this build reads version " +
             std::to_string(kMaterialSchemaVersion) + ")");
}

const ModelInfo& read_model(const Entry& e, std::string_view source) {
  const std::string name = read_string(e, source);
  if (const ModelInfo* info = find_model(name)) return *info;
  std::vector<std::string_view> known;
  for (const ModelInfo& m : models()) known.push_back(m.name);
  fail(source, e.line(), e.key, "unknown model '" + name + "' (known: " + join(known) + ")");
}

Rgb read_rgb(const Entry& e, std::string_view source) {
  if (!e.value.IsSequence())
    fail(source, e.line(), e.key, "expected a list [r, g, b], got " + describe(e.value));
  if (e.value.size() != 3)
    fail(source, e.line(), e.key,
         "expected 3 components [r, g, b], got " + std::to_string(e.value.size()));
  Rgb rgb;
  for (int i = 0; i < 3; ++i) {
    const YAML::Node component = e.value[i];
    rgb[i] =
        read_number(component, component.Mark(), source, e.key + "[" + std::to_string(i) + "]");
  }
  return rgb;
}

Mapping read_params_mapping(const Entry& e, const ModelInfo& info, std::string_view source) {
  if (!e.value.IsMap())
    fail(source, e.line(), e.key, "expected a mapping of parameters, got " + describe(e.value));
  std::vector<std::string_view> names;
  for (const ParamSpec& p : info.params) names.push_back(p.name);
  return Mapping(e.value, source, "params", std::move(names), e.line());
}

// validate() starts its message with the offending key ("params.n: ..."); point at that key.
void validate_at_keys(const Material& m, std::string_view source, const Mapping& top,
                      const Mapping& params) {
  try {
    validate(m);
  } catch (const MaterialError& e) {
    const std::string_view what = e.what();
    const std::string_view key = what.substr(0, what.find(':'));
    const Entry* entry = top.find_key(key);
    if (!entry) entry = params.find_key(key);
    throw MaterialError(location(source, entry ? entry->line() : top.mark()) + std::string(what));
  }
}

void emit_rgb(YAML::Emitter& out, const char* key, const Rgb& rgb) {
  out << YAML::Key << key << YAML::Value << YAML::Flow << YAML::BeginSeq;
  for (int i = 0; i < 3; ++i) out << yaml_number(rgb[i]);
  out << YAML::EndSeq;
}

// Throws a syntax error where yaml-cpp's parser would stop making progress. yaml-cpp 0.7 reads a
// stray ',' at the top level as an empty document without consuming it, so YAML::LoadAll(",")
// appends empty documents until memory runs out (found by tests/fuzz). A call that consumes
// nothing starts its document where the previous one started; such a stall never ends.
void check_parser_progress(const std::string& text, std::string_view source) {
  struct DocumentStarts : YAML::EventHandler {
    std::vector<YAML::Mark> marks;
    void OnDocumentStart(const YAML::Mark& mark) override { marks.push_back(mark); }
    void OnDocumentEnd() override {}
    void OnNull(const YAML::Mark&, YAML::anchor_t) override {}
    void OnAlias(const YAML::Mark&, YAML::anchor_t) override {}
    void OnScalar(const YAML::Mark&, const std::string&, YAML::anchor_t,
                  const std::string&) override {}
    void OnSequenceStart(const YAML::Mark&, const std::string&, YAML::anchor_t,
                         YAML::EmitterStyle::value) override {}
    void OnSequenceEnd() override {}
    void OnMapStart(const YAML::Mark&, const std::string&, YAML::anchor_t,
                    YAML::EmitterStyle::value) override {}
    void OnMapEnd() override {}
  } starts;
  std::istringstream in(text);
  YAML::Parser parser(in);
  while (parser.HandleNextDocument(starts)) {
    const std::vector<YAML::Mark>& m = starts.marks;
    if (m.size() >= 2 && m.back().pos == m[m.size() - 2].pos) {
      const auto at = static_cast<std::size_t>(m.back().pos);
      const std::string what = at < text.size() ? "'" + text.substr(at, 1) + "'" : "end of input";
      throw MaterialError(location(source, m.back()) + "syntax error: unexpected " + what);
    }
  }
}

std::string read_text(const std::filesystem::path& path) {
  try {
    return read_file(path);
  } catch (const Error& e) {
    throw MaterialError(e.what(), ErrorCode::io);
  }
}

}  // namespace

std::string yaml_number(double v) {
  std::array<char, 32> buf;
  const auto [end, ec] = std::to_chars(buf.data(), buf.data() + buf.size(), v);
  std::string text(buf.data(), end);
  // "1e-05" -> "1.0e-05": YAML 1.1 readers (PyYAML) read a float without a '.' as a string.
  const std::size_t e = text.find('e');
  if (e != std::string::npos && text.find('.') == std::string::npos) text.insert(e, ".0");
  return text;
}

Material material_from_node(const YAML::Node& node, std::string_view source,
                            bool schema_key_required, bool export_keys_allowed) {
  if (!node.IsMap())
    fail(source, node.Mark(), "material", "expected a mapping, got " + describe(node));
  std::vector<std::string_view> allowed(kTopLevelKeys.begin(), kTopLevelKeys.end());
  if (export_keys_allowed) allowed.insert(allowed.end(), kExportKeys.begin(), kExportKeys.end());
  const Mapping top(node, source, "", std::move(allowed), node.Mark());
  if (const Entry* schema = top.find("brdfnav_material")) {
    check_schema_version(*schema, source);
  } else if (schema_key_required) {
    top.missing("brdfnav_material");
  }
  const ModelInfo& info = read_model(top.require("model"), source);
  const Mapping params = read_params_mapping(top.require("params"), info, source);

  Material m;
  m.model = info.id;
  for (const ParamSpec& p : info.params) {
    const Entry& e = params.require(p.name);
    m.params.push_back(read_number(e.value, e.line(), source, e.key));
  }
  m.rho_d = read_rgb(top.require("rho_d"), source);
  m.rho_s = read_rgb(top.require("rho_s"), source);
  m.colorspace = read_string(top.require("colorspace"), source);
  validate_at_keys(m, source, top, params);
  return m;
}

Material parse_material_yaml(std::string_view text, std::string_view source) {
  const std::string copy(text);
  std::vector<YAML::Node> documents;
  try {
    check_parser_progress(copy, source);
    documents = YAML::LoadAll(copy);
  } catch (const YAML::Exception& e) {
    throw MaterialError(location(source, e.mark) + "syntax error: " + e.msg);
  }
  if (documents.empty() || documents.front().IsNull())
    fail(source, YAML::Mark(), "material",
         "the file is empty, expected a brdfnav_material mapping");
  if (documents.size() > 1)
    fail(source, documents[1].Mark(), "material",
         "expected one YAML document, got " + std::to_string(documents.size()));
  return material_from_node(documents.front(), source, true, true);
}

Material read_material_yaml(const std::filesystem::path& path) {
  return parse_material_yaml(read_text(path), path.string());
}

void emit_material(YAML::Emitter& out, const Material& m, bool schema_key) {
  validate(m);
  const ModelInfo& info = model_info(m.model);
  if (schema_key) out << YAML::Key << "brdfnav_material" << YAML::Value << kMaterialSchemaVersion;
  out << YAML::Key << "model" << YAML::Value << std::string(info.name);
  out << YAML::Key << "params" << YAML::Value << YAML::Flow << YAML::BeginMap;
  for (std::size_t i = 0; i < info.params.size(); ++i)
    out << YAML::Key << std::string(info.params[i].name) << YAML::Value << yaml_number(m.params[i]);
  out << YAML::EndMap;
  emit_rgb(out, "rho_d", m.rho_d);
  emit_rgb(out, "rho_s", m.rho_s);
  // Quoted, so that names YAML would read as something else (null, true, 1.5) stay strings.
  out << YAML::Key << "colorspace" << YAML::Value << YAML::DoubleQuoted << m.colorspace;
}

std::string material_to_yaml(const Material& m) {
  YAML::Emitter out;
  out << YAML::BeginMap;
  emit_material(out, m, true);
  out << YAML::EndMap;
  if (!out.good())
    throw MaterialError("material: cannot be written as YAML: " + out.GetLastError());
  return std::string(out.c_str()) + "\n";
}

void write_material_yaml(const std::filesystem::path& path, const Material& m) {
  write_file_atomic(path, material_to_yaml(m));
}

Material load_material(std::string_view path_or_spec) {
  const std::filesystem::path path(path_or_spec);
  std::error_code ec;
  if (std::filesystem::exists(path, ec)) return read_material_yaml(path);
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension == ".yaml" || extension == ".yml")
    throw MaterialError(path.string() + ": no such material file", ErrorCode::io);
  // Neither a spec ("model:key=value,...") nor a bare model name: a file name that was mistyped
  // or lacks its extension, which "unknown model" would not tell.
  const bool spec =
      path_or_spec.find(':') != std::string_view::npos || find_model(path_or_spec) != nullptr;
  if (!spec) {
    std::string models;
    for (const ModelInfo& info : brdfnav::models())
      models += (models.empty() ? "" : ", ") + std::string(info.name);
    throw MaterialError(path.string() +
                            ": no such material file, and not a model name or an inline spec "
                            "(MODEL:key=value,...; models: " +
                            models + ")",
                        ErrorCode::io);
  }
  return parse_material_spec(path_or_spec);
}

}  // namespace brdfnav
