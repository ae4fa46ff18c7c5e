// The export of a chosen material in the formats renderers read (docs/HOSTS.md): MaterialX 1.38
// and Cycles (what hosts/blender/brdfnav_cycles.py reads), beside brdfnav's own YAML. A renderer
// takes the `ggx` model: a material of another model goes out as its best `ggx` fit, and the
// document states in the image metric how far what the renderer will show is from what brdfnav
// showed, rendered by brdfnav under the database's environment map.
#pragma once

#include <brdfnav/navigator/navigator.h>

#include <nlohmann/json.hpp>

#include <string>
#include <string_view>
#include <vector>

namespace brdfnav::lookdev {

enum class ExportFormat { yaml, materialx, cycles };

// "yaml", "materialx", "cycles".
const std::vector<std::string>& export_format_names();
// Error(invalid_argument) naming "format" and the choices for an unknown name.
ExportFormat parse_export_format(std::string_view name);
std::string_view export_content_type(ExportFormat format);
std::string_view export_extension(ExportFormat format);  // ".yaml", ".mtlx", ".json"

// What a renderer's export states.
struct RendererExport {
  Material chosen;  // the material as chosen
  Material ggx;     // what the renderer gets: `chosen` itself if it is ggx, else its fit
  double embedded_residual = 0;  // the database's estimate of distance(chosen, ggx)
  // Measured by brdfnav's renderer at resolution x resolution under the database's map and
  // scene, as the image metric (cube-root RMS):
  int resolution = 0;
  std::string environment, scene;
  double residual = 0;  // chosen against ggx (0 when chosen is ggx)
  // ... for the MaterialX document only (else 0):
  double materialx_masking = 0;  // ggx against ggx with MaterialX's masking-shadowing alone
  double materialx = 0;          // ggx against ggx with all of MaterialX's terms
};

// The ggx form of `chosen` and the measures, rendered at `resolution` (0: the database's), those
// of MaterialX's terms for `format` materialx.
// Throws NavigatorError when the database holds no ggx model, and load_database_env()'s
// Error(database) when its environment map is missing or no longer the one it was built with.
RendererExport make_renderer_export(const Navigator& navigator, const Material& chosen,
                                    ExportFormat format, int resolution);

// A MaterialX 1.38 document with one surfacematerial (pbrlib nodes) and a comment that states
// the residual and where MaterialX's definition differs from the ggx closure.
std::string materialx_document(const RendererExport& e);
// The JSON hosts/blender/brdfnav_cycles.py reads (schema `brdfnav_cycles: 1`).
std::string cycles_document(const RendererExport& e);

// The export of `chosen` in `format`: export_to_yaml() for yaml, else one of the two above.
std::string export_document(const Navigator& navigator, const Material& chosen, ExportFormat format,
                            int resolution);

}  // namespace brdfnav::lookdev
