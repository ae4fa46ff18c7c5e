// The YAML documents of navigation (docs/NAVIGATION.md): the neighbour list `brdfnav neighbors`
// prints and the export `brdfnav export` writes. Materials inside them use the material schema
// of material_yaml.h; an export reads back as a material wherever a material file is accepted.
#pragma once

#include <brdfnav/navigator/navigator.h>

#include <filesystem>
#include <string>
#include <vector>

namespace brdfnav {

// One document with a top-level `neighbors:` list; each item has `tab`, `label`, `distance`,
// `flags` (a list of at_boundary / clamped, empty when none) and `material` (the material
// schema without its `brdfnav_material` key).
std::string neighbors_to_yaml(const std::vector<Neighbor>& neighbors);

// The material (schema `brdfnav_material: 1`), its `provenance` (database, manifest SHA-1,
// environment map and metric) and its `equivalents` in every other model of the database.
std::string export_to_yaml(const Navigator& navigator, const Material& m);
// export_to_yaml() written atomically.
void write_export(const std::filesystem::path& path, const Navigator& navigator, const Material& m);

}  // namespace brdfnav
