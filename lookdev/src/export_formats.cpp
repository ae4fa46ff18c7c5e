#include <brdfnav/lookdev/export_formats.h>

#include <brdfnav/lookdev/database_env.h>
#include <brdfnav/navigator/navigation_json.h>
#include <brdfnav/navigator/navigation_yaml.h>
#include <brdfnav/renderer/render.h>

#include <algorithm>
#include <cstdio>
#include <iterator>
#include <stdexcept>
#include <utility>

namespace brdfnav::lookdev {

namespace {

std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", v);
  return text;
}

std::string color(const Rgb& c) {
  return number(c[0]) + ", " + number(c[1]) + ", " + number(c[2]);
}

// XML comments may not hold "--" (a path or a spec might).
std::string comment_safe(std::string text) {
  for (std::size_t at = text.find("--"); at != std::string::npos; at = text.find("--", at))
    text.replace(at, 2, "- -");
  return text;
}

// A distance as the comments give it.
std::string short_number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", v);
  return text;
}

// The inline spec with six digits, for people (format_material_spec() writes every digit).
std::string readable_spec(const Material& m) {
  const ModelInfo& info = model_info(m.model);
  char text[64];
  std::string out(info.name);
  for (std::size_t i = 0; i < info.params.size(); ++i) {
    std::snprintf(text, sizeof text, "%s%s=%.6g", i == 0 ? ":" : ",",
                  std::string(info.params[i].name).c_str(), m.params[i]);
    out += text;
  }
  for (const auto& [key, c] : {std::pair{"rho_d", m.rho_d}, std::pair{"rho_s", m.rho_s}}) {
    std::snprintf(text, sizeof text, ",%s=%.6g/%.6g/%.6g", key, c[0], c[1], c[2]);
    out += text;
  }
  return out;
}

// Where the distances were rendered, for the documents.
std::string where_measured(const RendererExport& e) {
  return std::to_string(e.resolution) + " x " + std::to_string(e.resolution) + " (" + e.scene +
         " under " + e.environment + ")";
}

// What the renderer gets, and how far it is from what was chosen.
std::string residual_text(const RendererExport& e) {
  if (e.chosen.model == ModelId::ggx)
    return "The chosen material, exported as it is:\n  " + readable_spec(e.ggx);
  return "The chosen material:\n  " + readable_spec(e.chosen) +
         "\nexported as its ggx equivalent (the database's best fit):\n  " + readable_spec(e.ggx) +
         "\nWhat a renderer shows of it differs from what brdfnav showed of the chosen\n"
         "material by " +
         short_number(e.residual) +
         " in brdfnav's image metric (cube-root RMS between brdfnav's\nrenders at " +
         where_measured(e) + ";\nthe database's estimate: " + short_number(e.embedded_residual) +
         ").";
}

// `text` as the lines of an XML comment indented by `indent`.
std::string comment_lines(const std::string& text, const std::string& indent) {
  std::string out;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    if (end > start) out += indent + text.substr(start, end - start);
    out += "\n";
    start = end + 1;
  }
  return out;
}

}  // namespace

namespace {

// Each format's name, content type and file extension, in ExportFormat order.
struct FormatInfo {
  std::string_view name, content_type, extension;
};
constexpr FormatInfo kFormats[] = {{"yaml", "application/yaml", ".yaml"},
                                   {"materialx", "application/xml", ".mtlx"},
                                   {"cycles", "application/json", ".json"}};

const FormatInfo& info_of(ExportFormat format) {
  return kFormats[static_cast<std::size_t>(format)];
}

}  // namespace

const std::vector<std::string>& export_format_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> out;
    for (const FormatInfo& f : kFormats) out.emplace_back(f.name);
    return out;
  }();
  return names;
}

ExportFormat parse_export_format(std::string_view name) {
  for (std::size_t i = 0; i < std::size(kFormats); ++i)
    if (kFormats[i].name == name) return static_cast<ExportFormat>(i);
  throw Error(ErrorCode::invalid_argument, "format",
              "'" + std::string(name) + "' is not one of yaml, materialx, cycles");
}

std::string_view export_content_type(ExportFormat format) {
  return info_of(format).content_type;
}

std::string_view export_extension(ExportFormat format) {
  return info_of(format).extension;
}

RendererExport make_renderer_export(const Navigator& navigator, const Material& chosen,
                                    ExportFormat format, int resolution) {
  validate(chosen);
  require_render_colorspace(chosen);
  RendererExport e;
  e.chosen = chosen;
  e.ggx = chosen;
  const Database& db = navigator.database();
  if (chosen.model != ModelId::ggx) {
    bool found = false;
    for (const Equivalent& q : navigator.equivalents(chosen)) {
      if (q.material.model != ModelId::ggx) continue;
      e.ggx = q.material;
      e.embedded_residual = q.residual;
      found = true;
    }
    if (!found)
      throw NavigatorError("format: the database " + db.dir().string() +
                           " holds no ggx model, which renderers take: build it again with this "
                           "brdfnav (brdfnav precompute) to export for renderers");
  }
  const Manifest& manifest = db.manifest();
  e.resolution = resolution > 0 ? resolution : manifest.resolution;
  e.environment = manifest.env_path;
  e.scene = manifest.scene;
  // A ggx material for Cycles, whose GGX it is: nothing to measure.
  if (chosen.model == ModelId::ggx && format != ExportFormat::materialx) return e;
  const EnvMap env = load_database_env(db);
  const Scene scene = Scene::load(manifest.scene);
  Renderer renderer(env, scene, e.resolution);
  const Image ggx = renderer.render(e.ggx);
  if (chosen.model != ModelId::ggx) e.residual = image_distance(renderer.render(chosen), ggx);
  if (format != ExportFormat::materialx) return e;
  const Ggx lobe = std::get<Ggx>(make_lobe(ModelId::ggx, e.ggx.params));
  // MaterialX's image: rho_d I_diffuse + rho_s I_plain + rho_s^2 I_compensation.
  Image materialx =
      compose(renderer.diffuse(), renderer.materialx_ggx(lobe, false), e.ggx.rho_d, e.ggx.rho_s);
  e.materialx_masking = image_distance(ggx, materialx);
  const Image compensation = renderer.materialx_ggx(lobe, true);
  const Rgb rho_s2 = e.ggx.rho_s.square();
  for (std::size_t i = 0; i < materialx.rgba.size(); i += 4)
    for (int c = 0; c < 3; ++c)
      materialx.rgba[i + c] =
          static_cast<float>(materialx.rgba[i + c] + rho_s2[c] * compensation.rgba[i + c]);
  e.materialx = image_distance(ggx, materialx);
  return e;
}

std::string materialx_document(const RendererExport& e) {
  const ModelInfo& ggx = model_info(ModelId::ggx);
  const std::string alpha_x = number(e.ggx.params[0]), alpha_y = number(e.ggx.params[1]);
  std::string note = "brdfnav export for MaterialX renderers (MaterialX 1.38, pbrlib nodes).\n\n" +
                     residual_text(e) + "\n\n";
  note +=
      "The ggx material is f = rho_d / pi + rho_s D G / (4 cos_i cos_o): Lambert plus an\n"
      "anisotropic GGX lobe without Fresnel, as Cycles (Blender 3.4) renders its Glossy BSDF;\n"
      "D is the Trowbridge-Reitz distribution, G Smith's masking-shadowing in its separable\n"
      "form G1(wi) G1(wo). This document writes it as oren_nayar_diffuse_bsdf (roughness 0:\n"
      "Lambert) plus generalized_schlick_bsdf with color0 = color90 = rho_s (a Fresnel factor\n"
      "of rho_s at every angle) and roughness = (alpha_x, alpha_y), alpha_x along its tangent.\n"
      "Where MaterialX's definition of that node (as its GLSL implementation computes it)\n"
      "differs, in brdfnav's image metric (rendered at\n" +
      where_measured(e) +
      "):\n"
      "- masking-shadowing: Smith's height-correlated G2 with the isotropic alpha\n"
      "  sqrt(alpha_x alpha_y), for the separable anisotropic G1(wi) G1(wo): " +
      short_number(e.materialx_masking) +
      ";\n"
      "- energy compensation: the lobe times 1 + rho_s (1 - E(cos_o)) / E(cos_o), E its\n"
      "  directional albedo, which the ggx closure does not have: with the above, " +
      short_number(e.materialx) +
      ".\n"
      "The diffuse term and D are the same. A renderer with its own implementation of\n"
      "generalized_schlick_bsdf may differ in other terms.";
  std::string out = "<?xml version=\"1.0\"?>\n<materialx version=\"1.38\" colorspace=\"" +
                    e.ggx.colorspace + "\">\n  <!--\n" + comment_lines(comment_safe(note), "    ") +
                    "  -->\n";
  out +=
      "  <oren_nayar_diffuse_bsdf name=\"brdfnav_diffuse\" type=\"BSDF\">\n"
      "    <input name=\"color\" type=\"color3\" value=\"" +
      color(e.ggx.rho_d) +
      "\" />\n"
      "    <input name=\"roughness\" type=\"float\" value=\"0\" />\n"
      "  </oren_nayar_diffuse_bsdf>\n"
      "  <generalized_schlick_bsdf name=\"brdfnav_specular\" type=\"BSDF\">\n"
      "    <input name=\"color0\" type=\"color3\" value=\"" +
      color(e.ggx.rho_s) +
      "\" />\n"
      "    <input name=\"color90\" type=\"color3\" value=\"" +
      color(e.ggx.rho_s) +
      "\" />\n"
      "    <input name=\"roughness\" type=\"vector2\" value=\"" +
      alpha_x + ", " + alpha_y +
      "\" />\n"
      "    <input name=\"distribution\" type=\"string\" value=\"ggx\" />\n"
      "  </generalized_schlick_bsdf>\n"
      "  <add name=\"brdfnav_bsdf\" type=\"BSDF\">\n"
      "    <input name=\"in1\" type=\"BSDF\" nodename=\"brdfnav_diffuse\" />\n"
      "    <input name=\"in2\" type=\"BSDF\" nodename=\"brdfnav_specular\" />\n"
      "  </add>\n"
      "  <surface name=\"brdfnav_surface\" type=\"surfaceshader\">\n"
      "    <input name=\"bsdf\" type=\"BSDF\" nodename=\"brdfnav_bsdf\" />\n"
      "  </surface>\n"
      "  <surfacematerial name=\"brdfnav_" +
      std::string(ggx.name) +
      "\" type=\"material\">\n"
      "    <input name=\"surfaceshader\" type=\"surfaceshader\" nodename=\"brdfnav_surface\" "
      "/>\n"
      "  </surfacematerial>\n"
      "</materialx>\n";
  return out;
}

std::string cycles_document(const RendererExport& e) {
  nlohmann::ordered_json doc;
  doc["brdfnav_cycles"] = 1;
  doc["about"] =
      "brdfnav export for Cycles (Blender 3.4): hosts/blender/brdfnav_cycles.py builds a "
      "Diffuse BSDF of colour rho_d plus a Glossy (or Anisotropic) BSDF with the GGX "
      "distribution and colour rho_s from `material`, which Cycles renders as brdfnav does";
  doc["material"] = material_json(e.ggx);
  doc["residual"] = e.residual;
  doc["residual_metric"] =
      "image distance (cube-root RMS) between brdfnav's renders of `chosen` and `material` at " +
      where_measured(e) + "; 0 when `chosen` is of model ggx";
  doc["embedded_residual"] = e.embedded_residual;
  doc["chosen"] = material_json(e.chosen);
  return doc.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n";
}

std::string export_document(const Navigator& navigator, const Material& chosen, ExportFormat format,
                            int resolution) {
  if (format == ExportFormat::yaml) return export_to_yaml(navigator, chosen);
  const RendererExport e = make_renderer_export(navigator, chosen, format, resolution);
  return format == ExportFormat::materialx ? materialx_document(e) : cycles_document(e);
}

}  // namespace brdfnav::lookdev
