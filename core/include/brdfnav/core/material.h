// A material: {model, non-linear params, rho_d RGB, rho_s RGB, colour space}. The on-disk YAML
// form lives in the plugin (it needs yaml-cpp); the inline spec is parsed here.
#pragma once

#include <brdfnav/core/error.h>
#include <brdfnav/core/models.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace brdfnav {

// The colour space of materials, renders and the environment maps; the built-in OCIO config's
// scene-linear space (brdfnav/ocio/color_pipeline.h).
inline constexpr const char* kDefaultColorspace = "lin_rec709";

struct Material {
  ModelId model = ModelId::blinn_phong;
  std::vector<double> params;  // in the order of model_info(model).params
  Rgb rho_d = Rgb::Constant(0.2);
  Rgb rho_s = Rgb::Constant(0.04);
  std::string colorspace{kDefaultColorspace};
};

// Every parameter error names what is wrong and where (the key, and the file/line when known).
using MaterialError = LayerError<struct MaterialErrorTag, ErrorCode::parse>;

// Valid range of rho_d and rho_s components. rho_d <= 1 keeps the diffuse part energy-bounded;
// rho_s is a multiplier that may exceed 1 for lobes whose albedo is below 1 (Cook-Torrance f0).
inline constexpr double kRhoDMax = 1.0;
inline constexpr double kRhoSMax = 10.0;

// A material of `id` with every parameter at its default.
Material default_material(ModelId id);
// Throws MaterialError naming the first offending key ("params.alpha_x", "rho_d", ...).
void validate(const Material& m);
// Images and distances (the renderer, the database's embedding, thumbnails, the navigator) are
// computed in kDefaultColorspace, the space of the environment maps: rho_d and rho_s given in
// another space would be read as if they were in it. Until colours are converted, such a
// material is refused there: MaterialError (ErrorCode::invalid_argument) naming `colorspace`.
void require_render_colorspace(const Material& m);
// Closure of a validated material.
Closure make_closure(const Material& m);

// Parses `model:key=value,...` (e.g. `ward:alpha_x=0.1,alpha_y=0.05,rho_d=0.2,rho_s=0.04`).
// Missing parameters take their defaults; a scalar colour is grey, `a/b/c` is RGB. Keys:
// the model's parameters, rho_d, rho_s, colorspace. Throws MaterialError.
Material parse_material_spec(std::string_view spec);
// The inverse: every parameter and colour written with round-trip precision.
std::string format_material_spec(const Material& m);

}  // namespace brdfnav
