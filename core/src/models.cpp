#include <brdfnav/core/models.h>

#include <array>
#include <utility>

namespace brdfnav {

namespace {

template <typename L>
constexpr std::string_view formula_of() {
  if constexpr (requires { L::kFormula; })
    return L::kFormula;
  else
    return {};
}

template <typename L>
constexpr ModelInfo info_of(ModelId id) {
  return {id, L::kName, L::kTitle, L::kParams, MirrorLobe<L>, formula_of<L>()};
}

template <std::size_t... I>
constexpr std::array<ModelInfo, sizeof...(I)> build_table(std::index_sequence<I...>) {
  return {info_of<std::variant_alternative_t<I, Lobe>>(static_cast<ModelId>(I))...};
}

constexpr auto kModels = build_table(std::make_index_sequence<kModelCount>{});

template <std::size_t... I>
Lobe make_lobe_impl(std::size_t index, std::span<const double> p, std::index_sequence<I...>) {
  using Factory = Lobe (*)(std::span<const double>);
  static constexpr Factory factories[] = {
      +[](std::span<const double> q) { return Lobe(std::in_place_index<I>, q); }...};
  return factories[index](p);
}

}  // namespace

std::span<const ModelInfo> models() {
  return kModels;
}

const ModelInfo& model_info(ModelId id) {
  return kModels[static_cast<std::size_t>(id)];
}

const ModelInfo* find_model(std::string_view name) {
  for (const ModelInfo& m : kModels)
    if (m.name == name) return &m;
  return nullptr;
}

int find_param(const ModelInfo& model, std::string_view name) {
  for (std::size_t i = 0; i < model.params.size(); ++i)
    if (model.params[i].name == name) return static_cast<int>(i);
  return -1;
}

Lobe make_lobe(ModelId id, std::span<const double> params) {
  return make_lobe_impl(static_cast<std::size_t>(id), params,
                        std::make_index_sequence<kModelCount>{});
}

}  // namespace brdfnav
