// The material file format (schema key `brdfnav_material: 1`), read and written with yaml-cpp.
// Errors are MaterialError with "FILE:LINE: key: what is wrong".
#pragma once

#include <brdfnav/core/material.h>

#include <filesystem>
#include <string>
#include <string_view>

namespace YAML {
class Emitter;
class Node;
}  // namespace YAML

namespace brdfnav {

inline constexpr int kMaterialSchemaVersion = 1;

// Parses a whole YAML document; `source` names it in error messages (a path or "<stdin>"). The
// document may be an export (`brdfnav export`): its `provenance` and `equivalents` keys are
// accepted and ignored.
Material parse_material_yaml(std::string_view text, std::string_view source);
Material read_material_yaml(const std::filesystem::path& path);

// Reads the material mapping of a larger document (the `material:` of a neighbour list, an
// export's top level). `schema_key_required` says whether `brdfnav_material` must be present;
// `export_keys_allowed` accepts (and ignores) an export's `provenance` and `equivalents`. Any
// other unknown key is an error.
Material material_from_node(const YAML::Node& node, std::string_view source,
                            bool schema_key_required, bool export_keys_allowed = false);

// The YAML text of a material, with round-trip precision.
std::string material_to_yaml(const Material& m);
// Writes the material's keys (`brdfnav_material` only when `schema_key`) into the mapping `out`
// is inside, for documents that embed materials. Throws MaterialError for an invalid material.
void emit_material(YAML::Emitter& out, const Material& m, bool schema_key);
// The shortest text of `v` that reads back as the same double, readable by YAML 1.1 and 1.2.
std::string yaml_number(double v);
// Written atomically (temporary file, then rename).
void write_material_yaml(const std::filesystem::path& path, const Material& m);

// What every `--material` option accepts: an existing file (or a *.yaml / *.yml path) is read
// as YAML, anything else is parsed as an inline spec `model:key=value,...`.
Material load_material(std::string_view path_or_spec);

}  // namespace brdfnav
