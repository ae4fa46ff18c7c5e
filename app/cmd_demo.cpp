// `brdfnav demo`: a first look at the six closures for a newcomer — their lobes in the plane of
// incidence (a PNG plot and a CSV) and their directional albedo at a few angles (a table).
#include <brdfnav/studies/plot.h>
#include "command_options.h"
#include "commands.h"

#include <brdfnav/core/atomic_file.h>
#include <brdfnav/core/material.h>
#include <brdfnav/renderer/render.h>

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <string_view>

namespace brdfnav::cli {

namespace {

struct Setting {
  const char* label;
  const char* spec;
};

// One smooth and one rough setting per model, plus Lafortune's off-specular tilt.
constexpr Setting kSettings[] = {
    {"Blinn-Phong n=2000", "blinn_phong:n=2000"},
    {"Blinn-Phong n=20", "blinn_phong:n=20"},
    {"Ward alpha=0.05", "ward:alpha_x=0.05,alpha_y=0.05"},
    {"Ward alpha=0.3/0.1", "ward:alpha_x=0.3,alpha_y=0.1"},
    {"Cook-Torrance m=0.1", "cook_torrance:f0=0.04,m=0.1"},
    {"Cook-Torrance m=0.4", "cook_torrance:f0=0.5,m=0.4"},
    {"Lafortune cz=0.5774 n=300", "lafortune:cz=0.5773502691896258,n=300"},
    {"Lafortune cz=0.56 n=300", "lafortune:cz=0.56,n=300"},
    {"He sigma=0.1 tau=3", "he:sigma=0.1,tau=3,eta=1.5"},
    {"He sigma=1 tau=4", "he:sigma=1,tau=4,eta=1.5"},
    {"GGX alpha=0.05", "ggx:alpha_x=0.05,alpha_y=0.05"},
    {"GGX alpha=0.4/0.1", "ggx:alpha_x=0.4,alpha_y=0.1"},
};

// Directional albedo of the lobe (rho_d = 0, rho_s = 1) at outgoing polar angle theta_o,
// estimated with the closure's own importance sampler on a stratified 128 x 128 grid
// (deterministic), delta lobes included.
double directional_albedo(const Material& lobe_only, double theta_o) {
  const Closure c = make_closure(lobe_only);
  const Vec3 wo(std::sin(theta_o), 0, std::cos(theta_o));
  constexpr int kN = 128;
  double sum = 0;
  for (int i = 0; i < kN; ++i)
    for (int j = 0; j < kN; ++j) {
      const Vec2 u((i + 0.5) / kN, (j + 0.5) / kN);
      const double uc = ((i * 37 + j * 91) % kN + 0.5) / kN;  // decorrelated component choice
      if (const auto s = c.sample(wo, uc, u)) sum += luminance(s->f) * s->wi.z() / s->pdf;
    }
  return sum / (kN * kN);
}

void write_lobe_plot(const std::filesystem::path& dir) {
  const double theta_o = 45 * kPi / 180;
  const Vec3 wo(std::sin(theta_o), 0, std::cos(theta_o));
  std::vector<PlotSeries> series;
  std::ostringstream csv;
  csv << "setting,theta_i_deg,f_cos\n";
  for (std::size_t k = 0; k < std::size(kSettings); ++k) {
    Material m = parse_material_spec(kSettings[k].spec);
    m.rho_d = Rgb::Zero(), m.rho_s = Rgb::Ones();
    const Closure c = make_closure(m);
    PlotSeries s{kSettings[k].label, {}, {}, plot_color(k)};
    for (double deg = -89; deg <= 89; deg += 0.5) {
      const double t = deg * kPi / 180;
      const Vec3 wi(-std::sin(t), 0, std::cos(t));  // +45 deg is the mirror direction
      const double v = luminance(c.eval(wi, wo)) * wi.z();
      s.x.push_back(deg), s.y.push_back(v);
      csv << kSettings[k].label << ',' << deg << ',' << v << '\n';
    }
    series.push_back(std::move(s));
  }
  write_line_plot(dir / "lobes.png",
                  {"Lobes in the plane of incidence, viewed from 45 deg (rho_s = 1)",
                   "theta_i (deg); +45 is the mirror direction", "f cos(theta_i)", true},
                  series);
  write_file_atomic(dir / "lobes.csv", csv.str());
}

void print_albedo_table(const std::filesystem::path& dir) {
  std::ostringstream csv;
  csv << "setting,albedo_0deg,albedo_45deg,albedo_75deg\n";
  std::printf("\nDirectional albedo of the lobe alone (rho_d = 0, rho_s = 1):\n");
  std::printf("  %-28s %9s %9s %9s\n", "setting", "0 deg", "45 deg", "75 deg");
  for (const Setting& s : kSettings) {
    Material m = parse_material_spec(s.spec);
    m.rho_d = Rgb::Zero(), m.rho_s = Rgb::Ones();
    const double a0 = directional_albedo(m, 0), a45 = directional_albedo(m, kPi / 4),
                 a75 = directional_albedo(m, 75 * kPi / 180);
    std::printf("  %-28s %9.4f %9.4f %9.4f\n", s.label, a0, a45, a75);
    csv << s.label << ',' << a0 << ',' << a45 << ',' << a75 << '\n';
  }
  write_file_atomic(dir / "albedo.csv", csv.str());
}

// A setting's label in two lines, the model and its parameters ("Blinn-Phong", "n=2000").
std::array<std::string, 2> label_lines(std::string_view label) {
  const std::size_t space = label.find(' ');
  if (space == std::string_view::npos) return {std::string(label), ""};
  return {std::string(label.substr(0, space)), std::string(label.substr(space + 1))};
}

// Every setting rendered on the sphere under the environment, in one labelled sheet (sRGB): a
// grid of cells as wide as the widest label line, each label centred under its sphere, with a
// margin around and between cells so that no label runs into its neighbour or off the sheet.
void write_sphere_sheet(const std::filesystem::path& dir, const RenderSetup& setup) {
  namespace IBA = OIIO::ImageBufAlgo;
  const EnvMap env = load_env(setup);
  const Scene scene = load_scene(setup);
  Renderer renderer(env, scene, setup.resolution);
  const int res = setup.resolution, columns = 6, gap = 12, font = 13;
  const int line = font + font / 3, label_h = 6 + 2 * line;
  const char* font_name = "DejaVuSans";
  int cell_w = res;
  for (const auto& setting : kSettings)
    for (const std::string& text : label_lines(setting.label))
      cell_w = std::max(cell_w, IBA::text_size(text, font, font_name).width());
  const int rows = static_cast<int>((std::size(kSettings) + columns - 1) / columns);
  OIIO::ImageBuf sheet(OIIO::ImageSpec(columns * cell_w + (columns + 1) * gap,
                                       rows * (res + label_h) + (rows + 1) * gap, 3,
                                       OIIO::TypeDesc::FLOAT));
  IBA::fill(sheet, {0.18f, 0.18f, 0.18f});
  const float white[] = {1.f, 1.f, 1.f};
  for (std::size_t k = 0; k < std::size(kSettings); ++k) {
    Material m = parse_material_spec(kSettings[k].spec);
    m.rho_d = Rgb::Constant(0.05), m.rho_s = Rgb::Constant(0.5);
    const Image img = renderer.render(m);
    OIIO::ImageBuf tile(OIIO::ImageSpec(res, res, 4, OIIO::TypeDesc::FLOAT));
    tile.set_pixels(OIIO::ROI::All(), OIIO::TypeDesc::FLOAT, img.rgba.data());
    const int x = gap + int(k % columns) * (cell_w + gap);
    const int y = gap + int(k / columns) * (res + label_h + gap);
    IBA::paste(sheet, x + (cell_w - res) / 2, y, 0, 0, IBA::colorconvert(tile, "linear", "sRGB"),
               OIIO::ROI(0, res, 0, res, 0, 1, 0, 3));
    const auto lines = label_lines(kSettings[k].label);
    for (std::size_t i = 0; i < lines.size(); ++i)
      IBA::render_text(sheet, x + cell_w / 2, y + res + 6 + font + int(i) * line, lines[i], font,
                       font_name, white, IBA::TextAlignX::Center);
    std::fprintf(stderr, "rendered %s\n", kSettings[k].label);
  }
  sheet.set_write_format(OIIO::TypeDesc::UINT8);
  AtomicOutput out(dir / "spheres.png");
  if (!sheet.write(out.temp_path().string()))
    throw Error(ErrorCode::io, (dir / "spheres.png").string(), sheet.geterror());
  out.commit();
}

}  // namespace

void add_demo_command(CLI::App& app) {
  auto* demo = app.add_subcommand(
      "demo", "Plot the six models' lobes, tabulate their albedo and render them on a sphere");
  auto out = std::make_shared<std::string>("out/demo");
  auto setup = std::make_shared<RenderSetup>();
  setup->resolution = 128;
  demo->add_option("--out", *out, "Output directory")->capture_default_str();
  add_render_setup_options(*demo, *setup);
  demo->callback([=] {
    const std::filesystem::path dir(*out);
    std::filesystem::create_directories(dir);
    write_lobe_plot(dir);
    print_albedo_table(dir);
    write_sphere_sheet(dir, *setup);
    std::printf("\nWrote %s (lobes), %s (the settings on a sphere), %s and %s\n",
                (dir / "lobes.png").c_str(), (dir / "spheres.png").c_str(),
                (dir / "lobes.csv").c_str(), (dir / "albedo.csv").c_str());
  });
}

}  // namespace brdfnav::cli
