// The model registry, built from each lobe's own parameter table (no registration macros).
#pragma once

#include <brdfnav/core/closure.h>

#include <span>
#include <string_view>

namespace brdfnav {

// Order matches the alternatives of Lobe.
enum class ModelId : int { blinn_phong = 0, ward, cook_torrance, lafortune, he, ggx };
inline constexpr int kModelCount = static_cast<int>(std::variant_size_v<Lobe>);

struct ModelInfo {
  ModelId id;
  std::string_view name;   // canonical name: blinn_phong, ward, cook_torrance, lafortune, he, ggx
  std::string_view title;  // for people
  std::span<const ParamSpec> params;
  bool has_mirror;  // has a delta (mirror) term
  // The lobe's formula in a sentence or two of Markdown when the paper has none (L::kFormula,
  // GGX's), else empty; docs/CLOSURES.md has every model's formula.
  std::string_view formula;
};

std::span<const ModelInfo> models();
const ModelInfo& model_info(ModelId id);
// nullptr when no model has this canonical name.
const ModelInfo* find_model(std::string_view name);
// Index of a parameter in the model's table, or -1.
int find_param(const ModelInfo& model, std::string_view name);

// Builds the lobe of `id` from parameter values in table order. The values must be valid
// (see validate() in material.h); the lobe does not check them again.
Lobe make_lobe(ModelId id, std::span<const double> params);

}  // namespace brdfnav
