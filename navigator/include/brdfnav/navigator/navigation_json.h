// The JSON forms of a material and a neighbour, beside their YAML forms (navigation_yaml.h,
// material_yaml.h): what `brdfnav serve` answers (docs/SERVE.md) and the Cycles export holds.
// JSON is YAML's flow syntax, so a material in this form reads back through the material YAML
// reader, with its checks and messages.
#pragma once

#include <brdfnav/core/material.h>
#include <brdfnav/navigator/database.h>
#include <brdfnav/navigator/navigator.h>

#include <nlohmann/json.hpp>

namespace brdfnav {

// {model, params: {name: value, ...} in the model's parameter order, rho_d, rho_s, colorspace}.
nlohmann::ordered_json material_json(const Material& m);

// {tab, label, words, change, opposite, distance, flags, material}: flags as flag_names(),
// material as material_json().
nlohmann::ordered_json neighbor_json(const Neighbor& n);

// Where an image or a material came from: {database (its directory), manifest_sha1, profile,
// resolution, scene, environment: {path, pixel_sha1}, metric (in words)}. The one list of these
// fields: an export's `provenance` (navigation_yaml.h) and the server's `database` are written
// from it.
nlohmann::ordered_json provenance_json(const Database& db);

}  // namespace brdfnav
