#include <brdfnav/navigator/navigation_yaml.h>

#include <brdfnav/core/atomic_file.h>
#include <brdfnav/io/material_yaml.h>
#include <brdfnav/navigator/navigation_json.h>

#include <yaml-cpp/yaml.h>

namespace brdfnav {

namespace {

// `key:` followed by a material mapping without the schema key.
void emit_material_entry(YAML::Emitter& out, const Material& m) {
  out << YAML::Key << "material" << YAML::Value << YAML::BeginMap;
  emit_material(out, m, false);
  out << YAML::EndMap;
}

void emit_flags(YAML::Emitter& out, const Neighbor& n) {
  out << YAML::Key << "flags" << YAML::Value << YAML::Flow << YAML::BeginSeq;
  for (std::string_view flag : flag_names(n)) out << std::string(flag);
  out << YAML::EndSeq;
}

std::string finish(const YAML::Emitter& out) {
  if (!out.good())
    throw MaterialError("navigation: cannot be written as YAML: " + out.GetLastError());
  return std::string(out.c_str()) + "\n";
}

// A JSON value as YAML: objects as block mappings in their order, every string double-quoted
// (a hexadecimal digest such as 1234E567... would otherwise read back as a number).
void emit_json(YAML::Emitter& out, const nlohmann::ordered_json& value) {
  if (value.is_object()) {
    out << YAML::BeginMap;
    for (const auto& item : value.items()) {
      out << YAML::Key << item.key() << YAML::Value;
      emit_json(out, item.value());
    }
    out << YAML::EndMap;
  } else if (value.is_string()) {
    out << YAML::DoubleQuoted << value.get<std::string>();
  } else if (value.is_number_integer()) {
    out << value.get<long long>();
  } else {
    throw MaterialError("navigation: no YAML form for the JSON value " + value.dump());
  }
}

}  // namespace

std::string neighbors_to_yaml(const std::vector<Neighbor>& neighbors) {
  YAML::Emitter out;
  out << YAML::BeginMap << YAML::Key << "neighbors" << YAML::Value;
  // An empty list still parses as a list, not as null.
  if (neighbors.empty()) out << YAML::Flow;
  out << YAML::BeginSeq;
  for (const Neighbor& n : neighbors) {
    out << YAML::BeginMap;
    out << YAML::Key << "tab" << YAML::Value << std::string(tab_name(n.tab));
    out << YAML::Key << "label" << YAML::Value << YAML::DoubleQuoted << n.label;
    out << YAML::Key << "words" << YAML::Value << YAML::DoubleQuoted << n.words;
    out << YAML::Key << "change" << YAML::Value << YAML::DoubleQuoted << n.change;
    out << YAML::Key << "opposite" << YAML::Value << n.opposite;
    out << YAML::Key << "distance" << YAML::Value << yaml_number(n.distance);
    emit_flags(out, n);
    emit_material_entry(out, n.material);
    out << YAML::EndMap;
  }
  out << YAML::EndSeq << YAML::EndMap;
  return finish(out);
}

std::string export_to_yaml(const Navigator& navigator, const Material& m) {
  const std::vector<Equivalent> equivalents = navigator.equivalents(m);
  YAML::Emitter out;
  out << YAML::BeginMap;
  emit_material(out, m, true);
  out << YAML::Key << "provenance" << YAML::Value;
  emit_json(out, provenance_json(navigator.database()));
  out << YAML::Key << "equivalents" << YAML::Value;
  if (equivalents.empty()) out << YAML::Flow;
  out << YAML::BeginMap;
  for (const Equivalent& e : equivalents) {
    out << YAML::Key << std::string(model_info(e.material.model).name) << YAML::Value
        << YAML::BeginMap;
    out << YAML::Key << "residual" << YAML::Value << yaml_number(e.residual);
    emit_material_entry(out, e.material);
    out << YAML::EndMap;
  }
  out << YAML::EndMap << YAML::EndMap;
  return finish(out);
}

void write_export(const std::filesystem::path& path, const Navigator& navigator,
                  const Material& m) {
  write_file_atomic(path, export_to_yaml(navigator, m));
}

}  // namespace brdfnav
