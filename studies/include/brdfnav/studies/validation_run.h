// What `brdfnav validate` runs (docs/VALIDATION.md): its inputs (the maps, the scene and the
// database, loaded up front) and every study of the report on them, in order, each with a line
// on stderr when it is done. The command (app/cmd_validate.cpp) parses the options, calls these
// and writes the report (validation_report.h).
#pragma once

#include <brdfnav/precompute/database.h>
#include <brdfnav/renderer/env_map.h>
#include <brdfnav/renderer/scene.h>
#include <brdfnav/studies/validation_report.h>

#include <optional>
#include <string>
#include <vector>

namespace brdfnav {

// Blender's eight studio lights: by default every one is compared with the reference (itself
// left out), so that the report gives Figure 3's full matrix and the most representative map.
std::vector<std::string> studio_lights();

// Everything the studies read, loaded before any rendering (and before the output directory is
// made) so that a bad input fails at once and leaves nothing behind. With a database, its own
// map and scene are the reference: the report then speaks of the metric that database embodies.
struct ValidationInputs {
  std::string database_path;  // empty without a database
  std::optional<Database> db;
  std::string reference_path;
  EnvMap reference;
  Scene scene;
  std::vector<std::string> other_paths;  // `envs` without the reference map itself
  std::vector<EnvMap> others;

  // `reference_map`: the reference map's path without a database (ignored with one).
  ValidationInputs(const std::string& database, const std::string& reference_map,
                   const std::vector<std::string>& envs);
};

// The studies' sizes: the images' width and height, the random pairs of the embedding's error and
// the nodes per model of the fits' comparison.
struct ValidationSizes {
  int resolution = 128;
  int pairs = 50;
  int fit_samples = 20;
};

// Figures 2, 3, 8 and 9 under the reference map, Figures 2 and 3 under each other map and a
// constant environment, then with a database its embedding's and its fits' studies.
ValidationResults run_validation(const ValidationInputs& inputs, const ValidationSizes& sizes);

}  // namespace brdfnav
