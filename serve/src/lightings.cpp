#include <brdfnav/serve/lightings.h>

#include "api_request.h"

#include <brdfnav/navigator/navigation_json.h>

#include <algorithm>
#include <filesystem>
#include <optional>

namespace brdfnav::serve {

namespace {

// The lighting's name for people and URLs: the map's file stem, made unique by a count.
std::string lighting_id(const Manifest& m, const std::vector<std::string>& taken) {
  const std::string stem = std::filesystem::path(m.env_path).stem().string();
  std::string id = stem.empty() ? "lighting" : stem;
  for (int n = 2; std::find(taken.begin(), taken.end(), id) != taken.end(); ++n)
    id = stem + "-" + std::to_string(n);
  return id;
}

// Whether two databases would show the same images: the same map's pixels, profile and resolution.
bool same_lighting(const Manifest& a, const Manifest& b) {
  return a.env_pixel_sha1 == b.env_pixel_sha1 && a.profile == b.profile &&
         a.resolution == b.resolution;
}

}  // namespace

LightingsApi::LightingsApi(const std::vector<ApiOptions>& databases) {
  if (databases.empty()) throw Error(ErrorCode::invalid_argument, "--db", "no database given");
  for (const ApiOptions& options : databases) {
    const std::string dir = options.db.string();
    apis_.push_back(with_context(dir, [&] { return std::make_unique<NavigatorApi>(options); }));
    const Manifest& m = apis_.back()->navigator().database().manifest();
    for (std::size_t i = 0; i + 1 < apis_.size(); ++i) {
      const Database& earlier = apis_[i]->navigator().database();
      if (same_lighting(earlier.manifest(), m))
        throw Error(ErrorCode::invalid_argument, dir,
                    "the same map, profile and resolution as " + earlier.dir().string() + " (" +
                        m.env_path + ", " + m.profile + ", " + std::to_string(m.resolution) +
                        " px): serve one of them");
    }
    ids_.push_back(lighting_id(m, ids_));
  }
}

void LightingsApi::release_memory() const {
  for (const auto& api : apis_) api->release_memory();
}

std::size_t LightingsApi::index_of(const std::string& id, const char* field) const {
  const auto found = std::find(ids_.begin(), ids_.end(), id);
  if (found == ids_.end())
    throw request_error(
        field, "no lighting " + shown(json(id)) + " (expected one of: " + join(ids_) + ")");
  return std::size_t(found - ids_.begin());
}

std::size_t LightingsApi::lighting_of(const ApiRequest& request) const {
  const auto it = request.query.find("lighting");
  return it == request.query.end() ? 0 : index_of(it->second, "lighting");
}

ApiResponse LightingsApi::handle(const ApiRequest& request) const {
  if (request.path == "/api/lightings" && (request.method == "GET" || request.method == "HEAD"))
    return lightings();
  if (request.path == "/api/carry" && request.method == "POST") return carry(request);
  if (request.path == "/api/lightings")
    return method_not_allowed(request.method, request.path, "GET, HEAD");
  if (request.path == "/api/carry") return method_not_allowed(request.method, request.path, "POST");
  std::size_t lighting = 0;
  try {
    lighting = lighting_of(request);
  } catch (const Error& e) {
    return error_response(400, e.what());
  }
  return apis_[lighting]->handle(request);
}

ApiResponse LightingsApi::lightings() const {
  return answer([&] {
    json list = json::array();
    for (std::size_t i = 0; i < apis_.size(); ++i) {
      const Database& db = apis_[i]->navigator().database();
      const Manifest& m = db.manifest();
      json models = json::array();
      for (const ModelInfo& info : brdfnav::models())
        if (db.embedding(info.id)) models.push_back(info.name);
      list.push_back({{"id", ids_[i]},
                      {"map", std::filesystem::path(m.env_path).filename().string()},
                      {"path", m.env_path},
                      {"profile", m.profile},
                      {"resolution", m.resolution},
                      {"models", models}});
    }
    return json_response({{"lightings", list}, {"default", ids_.front()}});
  });
}

ApiResponse LightingsApi::carry(const ApiRequest& request) const {
  return answer([&] {
    if (request.body.size() > kMaxBodyBytes)
      throw request_error("body", "larger than " + std::to_string(kMaxBodyBytes) + " bytes");
    const json body = parse_body(request.body, {"material", "from"});
    const std::optional<std::string> from_id = optional_string(body, "from");
    if (!from_id) throw request_error("from", "missing");
    const Navigator& from = apis_[index_of(*from_id, "from")]->navigator();
    const Navigator& to = apis_[lighting_of(request)]->navigator();
    const Material m = read_material(from.database(), require(body, "material"));
    if (to.database().embedding(m.model))
      return json_response({{"material", material_json(m)}, {"carried", "same"}});
    std::optional<Equivalent> nearest;
    for (const Equivalent& e : from.equivalents(m))
      if (to.database().embedding(e.material.model) && (!nearest || e.residual < nearest->residual))
        nearest = e;
    if (!nearest)
      return json_response(
          {{"material", material_json(to.start_material())}, {"carried", "start"}});
    return json_response({{"material", material_json(nearest->material)},
                          {"carried", "nearest"},
                          {"residual", nearest->residual}});
  });
}

}  // namespace brdfnav::serve
