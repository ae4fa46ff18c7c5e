#include <brdfnav/navigator/navigation_json.h>

#include <string>

namespace brdfnav {

nlohmann::ordered_json material_json(const Material& m) {
  const ModelInfo& info = model_info(m.model);
  nlohmann::ordered_json params = nlohmann::ordered_json::object();
  for (std::size_t i = 0; i < info.params.size(); ++i)
    params[std::string(info.params[i].name)] = m.params[i];
  return {{"model", info.name},
          {"params", params},
          {"rho_d", {m.rho_d[0], m.rho_d[1], m.rho_d[2]}},
          {"rho_s", {m.rho_s[0], m.rho_s[1], m.rho_s[2]}},
          {"colorspace", m.colorspace}};
}

nlohmann::ordered_json neighbor_json(const Neighbor& n) {
  nlohmann::ordered_json flags = nlohmann::ordered_json::array();
  for (std::string_view flag : flag_names(n)) flags.push_back(std::string(flag));
  return {{"tab", tab_name(n.tab)}, {"label", n.label},
          {"words", n.words},       {"change", n.change},
          {"opposite", n.opposite}, {"distance", n.distance},
          {"flags", flags},         {"material", material_json(n.material)}};
}

nlohmann::ordered_json provenance_json(const Database& db) {
  const Manifest& m = db.manifest();
  return {{"database", db.dir().string()},
          {"manifest_sha1", db.manifest_sha1()},
          {"profile", m.profile},
          {"resolution", m.resolution},
          {"scene", m.scene},
          {"environment", {{"path", m.env_path}, {"pixel_sha1", m.env_pixel_sha1}}},
          {"metric",
           "cube-root RMS: sqrt(mean over the covered pixels and the RGB channels of "
           "(cbrt(a) - cbrt(b))^2) between renderings under the environment, through the "
           "database embedding"}};
}

}  // namespace brdfnav
