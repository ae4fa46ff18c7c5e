// `brdfnav render`: a material's BRDF image under an environment map; `brdfnav distance`: the
// metric between two images.
#include "command_options.h"
#include "commands.h"
#include "progress.h"

#include <brdfnav/core/atomic_file.h>
#include <brdfnav/io/material_yaml.h>
#include <brdfnav/navigator/image_input.h>
#include <brdfnav/renderer/image_output.h>
#include <brdfnav/renderer/render.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

namespace brdfnav::cli {

void add_render_commands(CLI::App& app) {
  auto* render = app.add_subcommand(
      "render", "Render a material on the scene under the environment map (linear RGBA EXR)");
  auto setup = std::make_shared<RenderSetup>();
  auto material = std::make_shared<std::string>();
  auto out = std::make_shared<std::string>();
  render->add_option("--material,-m", *material, "YAML file or inline spec")->required();
  add_render_setup_options(*render, *setup);
  render->add_option("--out,-o", *out, "Output OpenEXR file (written atomically)")->required();
  render->callback([=] {
    check_exr_name(*out);
    check_output_file(*out, "--out");
    const Material m = load_material(*material);
    const EnvMap env = load_env(*setup);
    const Scene geometry = load_scene(*setup);
    // Two passes, each with its own bar: the diffuse image, then the material's lobe (whose
    // first pass may filter the map around the mirror directions, with no progress of its own).
    Renderer renderer(env, geometry, setup->resolution, {});
    renderer.set_progress(stderr_progress("render: "));
    write_exr(renderer.render(m), *out, render_metadata(renderer, &m));
  });

  auto* distance = app.add_subcommand(
      "distance", "Print the cube-root RMS distance between two BRDF images (same mask)");
  auto a = std::make_shared<std::string>(), b = std::make_shared<std::string>();
  distance->add_option("a", *a, "First image (OpenEXR)")->required();
  distance->add_option("b", *b, "Second image (OpenEXR)")->required();
  distance->callback(
      [=] { std::printf("%.9g\n", image_distance(read_image(*a), read_image(*b))); });
}

}  // namespace brdfnav::cli
