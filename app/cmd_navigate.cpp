// `brdfnav neighbors`: a material's variations at equal visual distance, as YAML;
// `brdfnav variations`: the same as a labelled contact sheet through OCIO;
// `brdfnav export`: a chosen material with its provenance and its equivalents in the other
// models. All read a database made by `brdfnav precompute` (docs/NAVIGATION.md).
#include <brdfnav/lookdev/exact_thumbnails.h>
#include <brdfnav/lookdev/export_formats.h>
#include "command_options.h"
#include "commands.h"

#include <brdfnav/core/atomic_file.h>

#include <brdfnav/io/material_yaml.h>
#include <brdfnav/navigator/navigation_yaml.h>
#include <brdfnav/navigator/navigator.h>
#include <brdfnav/navigator/thumbnails.h>
#include <brdfnav/ocio/color_pipeline.h>
#include <brdfnav/ocio/contact_sheet.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <stdexcept>

namespace brdfnav::cli {

namespace {

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
  return with_context("--db", [&] { return Navigator::open(in.db, options); });
}

Material load_current(const Inputs& in) {
  return with_context("--material", [&] { return load_material(in.material); });
}

void add_neighbors_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("neighbors",
                                 "Print a material's neighbours at embedded (or, --exact, "
                                 "rendered) distance --radius, as YAML");
  auto in = std::make_shared<Inputs>();
  auto radius = std::make_shared<double>(0);
  auto tab = std::make_shared<std::string>("all");
  auto k = std::make_shared<int>(8);
  auto format = std::make_shared<std::string>("yaml");
  add_inputs(*cmd, *in);
  cmd->add_option("--radius,-r", *radius, "Distance eps (cube-root RMS metric units)")
      ->required()
      ->check(radius_validator());
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
  auto exact = std::make_shared<bool>(false);
  cmd->add_flag("--exact", *exact,
                "Move each offer until a render of it is at --radius from a render of the "
                "material (the database's map, scene and resolution; a few renders per offer)");
  cmd->callback([=] {
    const Navigator navigator = open_navigator(*in);
    const Material current = load_current(*in);
    std::optional<lookdev::ExactThumbnails> renders;
    std::optional<ExactSteps> steps;
    if (*exact) {
      renders.emplace(navigator.database(), navigator.database().manifest().resolution);
      steps = renders->steps_from(current);
    }
    std::vector<Neighbor> all;
    for (Tab t : kTabs) {
      if (*tab != "all" && *tab != tab_name(t)) continue;
      std::vector<Neighbor> some =
          navigator.neighbors(current, *radius, t, *k, steps ? &*steps : nullptr);
      all.insert(all.end(), some.begin(), some.end());
    }
    std::fputs(neighbors_to_yaml(all).c_str(), stdout);
  });
}

ocio::SheetTile tile(const Thumbnails& thumbnails, const ocio::ColorPipeline& pipeline,
                     const std::string& display, const std::string& view, const Material& m,
                     std::vector<std::string> label) {
  const Image img = thumbnails.render(m);
  return {{img.width, img.height,
           pipeline.apply(img.rgba.data(), img.width, img.height, display, view)},
          std::move(label)};
}

void add_variations_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "variations", "Write a labelled contact sheet of a material's neighbours in one tab (PNG)");
  auto in = std::make_shared<Inputs>();
  auto radius = std::make_shared<double>(0);
  auto tab = std::make_shared<std::string>("lobe");
  auto display = std::make_shared<std::string>(), view = std::make_shared<std::string>();
  auto size = std::make_shared<int>(128);
  auto out = std::make_shared<std::string>();
  add_inputs(*cmd, *in);
  cmd->add_option("--radius,-r", *radius, "Distance eps (cube-root RMS metric units)")
      ->required()
      ->check(radius_validator());
  std::vector<std::string> tabs = tab_choices();
  tabs.pop_back();  // one tab per sheet
  cmd->add_option("--tab", *tab, "lobe, diffuse, specular, models or gallery")
      ->capture_default_str()
      ->check(CLI::IsMember(tabs));
  cmd->add_option("--display", *display, "OCIO display (default: the config's)");
  cmd->add_option("--view", *view, "OCIO view (default: the display's)");
  cmd->add_option("--size", *size, "Thumbnail width and height")
      ->capture_default_str()
      ->check(CLI::Range(16, 1024));
  cmd->add_option("--out,-o", *out, "PNG file to write (atomically)")->required();
  cmd->callback([=] {
    const Navigator navigator = open_navigator(*in);
    const Material current = load_current(*in);
    const ocio::ColorPipeline pipeline;
    const std::string d = display->empty() ? pipeline.default_display() : *display;
    const std::string v = view->empty() ? pipeline.default_view(d) : *view;
    with_context("--display/--view", [&] { pipeline.validate(d, v); });
    const Thumbnails thumbnails(navigator.database(), *size);
    const Tab t = *find_tab(*tab);
    std::vector<ocio::SheetTile> tiles;
    // The navigator gives the offers in ring order (opposites face each other on the sheet).
    for (const Neighbor& n : navigator.neighbors(current, *radius, t)) {
      char distance[32];
      std::snprintf(distance, sizeof distance, "d=%.4f", n.distance);
      std::vector<std::string> label{n.words, distance};
      if (n.at_boundary) label.emplace_back("at the range's end");
      if (n.clamped) label.emplace_back("colour clamped");
      if (n.beyond_radius) label.emplace_back("beyond the radius");
      tiles.push_back(tile(thumbnails, pipeline, d, v, n.material, std::move(label)));
    }
    ocio::SheetOptions options;
    options.tile_size = *size;
    char title[160];
    std::snprintf(title, sizeof title, "%s, %s tab, eps %.4g, %s / %s",
                  std::string(model_info(current.model).name).c_str(), tab->c_str(), *radius,
                  d.c_str(), v.c_str());
    options.title = title;
    const ocio::SheetTile centre = tile(thumbnails, pipeline, d, v, current,
                                        {"current", std::string(model_info(current.model).name)});
    ocio::write_contact_sheet(*out, centre, tiles, options);
  });
}

void add_export_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "export",
      "Write a material for brdfnav (its provenance and best fit in every other model) or for a "
      "renderer (its ggx form, MaterialX or Cycles, with the residual in the image metric)");
  auto in = std::make_shared<Inputs>();
  auto out = std::make_shared<std::string>();
  auto format = std::make_shared<std::string>("yaml");
  auto resolution = std::make_shared<int>(0);
  add_inputs(*cmd, *in);
  cmd->add_option("--out,-o", *out, "File to write (atomically)")->required();
  cmd->add_option("--format", *format,
                  "yaml (brdfnav's), materialx (a MaterialX 1.38 document) or cycles (what "
                  "hosts/blender/brdfnav_cycles.py reads)")
      ->capture_default_str()
      ->check(CLI::IsMember(lookdev::export_format_names()));
  cmd->add_option("--res", *resolution,
                  "materialx, cycles: the resolution at which the residuals are rendered "
                  "(default: the database's)")
      ->check(CLI::Range(8, 4096));
  cmd->callback([=] {
    const Navigator navigator = open_navigator(*in);
    write_file_atomic(*out,
                      lookdev::export_document(navigator, load_current(*in),
                                               lookdev::parse_export_format(*format), *resolution));
  });
}

}  // namespace

void add_navigate_commands(CLI::App& app) {
  add_neighbors_command(app);
  add_variations_command(app);
  add_export_command(app);
}

}  // namespace brdfnav::cli
