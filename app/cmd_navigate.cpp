// `brdfnav neighbors`: a material's variations at equal visual distance, as YAML;
// `brdfnav export`: a chosen material with its provenance and its equivalents in the other
// models. Both read a database made by `brdfnav precompute` (docs/NAVIGATION.md).
#include "commands.h"

#include <brdfnav/io/material_yaml.h>
#include <brdfnav/io/navigation_yaml.h>
#include <brdfnav/navigator.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>

namespace brdfnav::cli {

namespace {

// Runs `body`, prefixing any failure with the option whose value caused it.
template <typename Body>
auto for_option(const char* option, Body&& body) {
  try {
    return body();
  } catch (const std::exception& e) {
    throw std::runtime_error(std::string(option) + ": " + e.what());
  }
}

// CLI11's PositiveNumber lets NaN through (NaN <= 0 is false).
const CLI::Validator kPositiveFinite(
    [](std::string& text) -> std::string {
      try {
        std::size_t used = 0;
        const double value = std::stod(text, &used);
        if (used == text.size() && std::isfinite(value) && value > 0) return "";
      } catch (const std::exception&) {
      }
      return "must be a positive finite distance, got '" + text + "'";
    },
    "POSITIVE");

std::vector<std::string> tab_choices() {
  std::vector<std::string> names;
  for (Tab tab : kTabs) names.emplace_back(tab_name(tab));
  names.emplace_back("all");
  return names;
}

struct Inputs {
  std::string db, material;
  int threads = 1;
};

void add_inputs(CLI::App& cmd, Inputs& in) {
  cmd.add_option("--db", in.db, "Database directory (brdfnav precompute)")->required();
  cmd.add_option("--material,-m", in.material, "YAML file (or an export) or inline spec")
      ->required();
}

Navigator open_navigator(const Inputs& in) {
  NavigatorOptions options;
  options.threads = in.threads;
  return for_option("--db", [&] { return Navigator::open(in.db, options); });
}

Material load_current(const Inputs& in) {
  return for_option("--material", [&] { return load_material(in.material); });
}

void add_neighbors_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "neighbors", "Print a material's neighbours at embedded distance --radius, as YAML");
  auto in = std::make_shared<Inputs>();
  auto radius = std::make_shared<double>(0);
  auto tab = std::make_shared<std::string>("all");
  auto k = std::make_shared<int>(8);
  auto format = std::make_shared<std::string>("yaml");
  add_inputs(*cmd, *in);
  cmd->add_option("--radius,-r", *radius, "Distance eps (cube-root RMS metric units)")
      ->required()
      ->check(kPositiveFinite);
  cmd->add_option("--tab", *tab, "lobe, diffuse, specular, models, gallery or all")
      ->capture_default_str()
      ->check(CLI::IsMember(tab_choices()));
  cmd->add_option("--k", *k, "Clusters of the models and gallery tabs")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000));
  cmd->add_option("--format", *format, "Output format")
      ->capture_default_str()
      ->check(CLI::IsMember({"yaml"}));
  cmd->add_option("--threads", in->threads, "Workers for k-means (answers do not depend on it)")
      ->capture_default_str()
      ->check(CLI::Range(1, 256));
  cmd->callback([=] {
    const Navigator navigator = open_navigator(*in);
    const Material current = load_current(*in);
    std::vector<Neighbor> all;
    for (Tab t : kTabs) {
      if (*tab != "all" && *tab != tab_name(t)) continue;
      std::vector<Neighbor> some = navigator.neighbors(current, *radius, t, *k);
      all.insert(all.end(), some.begin(), some.end());
    }
    std::fputs(neighbors_to_yaml(all).c_str(), stdout);
  });
}

void add_export_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "export", "Write a material with its provenance and its best fit in every other model");
  auto in = std::make_shared<Inputs>();
  auto out = std::make_shared<std::string>();
  add_inputs(*cmd, *in);
  cmd->add_option("--out,-o", *out, "YAML file to write (atomically)")->required();
  cmd->callback([=] {
    const Navigator navigator = open_navigator(*in);
    write_export(*out, navigator, load_current(*in));
  });
}

}  // namespace

void add_navigate_commands(CLI::App& app) {
  add_neighbors_command(app);
  add_export_command(app);
}

}  // namespace brdfnav::cli
