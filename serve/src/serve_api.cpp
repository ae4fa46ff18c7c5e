#include <brdfnav/serve/serve_api.h>

#include "api_request.h"

#include <brdfnav/lookdev/export_formats.h>
#include <brdfnav/serve/serve_memory.h>

#include <brdfnav/io/material_yaml.h>
#include <brdfnav/navigator/display_thumbnails.h>
#include <brdfnav/navigator/navigation_json.h>
#include <brdfnav/navigator/navigation_yaml.h>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>
#include <yaml-cpp/yaml.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <functional>
#include <iterator>
#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

namespace brdfnav::serve {

namespace {

// The page's radius slider: its range and start, in the metric's units (cube-root RMS), from
// where a step starts to show to about the distance between a matte and a glossy material. The
// navigator itself takes radii down to kMinRadius (the embedding's noise).
constexpr double kSliderMin = 0.002, kSliderMax = 0.2, kSliderStart = 0.03;
constexpr int kMaxClusters = 32;

double read_radius(const json& value) {
  if (!value.is_number()) throw request_error("radius", "expected a number, got " + shown(value));
  const double radius = value.get<double>();
  if (!valid_radius(radius))
    throw request_error("radius", radius_requirement() + ", got " + shown(value));
  return radius;
}

Tab read_tab(const json& value) {
  if (value.is_string())
    if (const std::optional<Tab> tab = find_tab(value.get<std::string>())) return *tab;
  std::vector<std::string> names;
  for (Tab t : kTabs) names.emplace_back(tab_name(t));
  throw request_error("tab",
                      "unknown tab " + shown(value) + " (expected one of: " + join(names) + ")");
}

// An optional true/false field, false when absent.
bool read_flag(const json& request, const char* key) {
  const auto it = request.find(key);
  if (it == request.end()) return false;
  if (!it->is_boolean()) throw request_error(key, "expected true or false, got " + shown(*it));
  return it->get<bool>();
}

// The optional {"client": "<page id>", "id": <ring number>} of a request: the work of a ring
// the page has left is dropped (serve_rings.h).
std::optional<RingId> read_ring(const json& request) {
  const auto it = request.find("ring");
  if (it == request.end()) return std::nullopt;
  const auto bad = [&] {
    return request_error("ring",
                         "expected {\"client\": a string of 1 to 64 letters, digits, '-' "
                         "or '_', \"id\": an integer of at least 0}, got " +
                             shown(*it));
  };
  if (!it->is_object() || it->size() != 2 || !it->contains("client") || !it->contains("id"))
    throw bad();
  const json& client = it->at("client");
  const json& id = it->at("id");
  if (!client.is_string() || !id.is_number_unsigned()) throw bad();
  const std::string name = client.get<std::string>();
  const bool word = std::all_of(name.begin(), name.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_';
  });
  if (name.empty() || name.size() > 64 || !word) throw bad();
  return RingId{name, id.get<std::uint64_t>()};
}

// Records the request's `ring` in `rings`, if it has one, and returns what its renders call
// first and while they run: it throws RingLeft once the page has asked for a later ring, which
// drops a render still to start and stops one under way (empty without a ring).
std::function<void()> enter_ring(LeftRings& rings, const json& request) {
  const std::optional<RingId> ring = read_ring(request);
  if (!ring) return nullptr;
  rings.enter(*ring);
  return rings.check(*ring);
}

// The "size" of a thumbnail: one of `sizes` (the first, the thumbnails' resolution, when absent).
int read_size(const json& request, const std::vector<int>& sizes) {
  const auto it = request.find("size");
  if (it == request.end()) return sizes.front();
  if (it->is_number_integer() &&
      std::find(sizes.begin(), sizes.end(), it->get<int>()) != sizes.end())
    return it->get<int>();
  std::vector<std::string> names;
  for (int s : sizes) names.push_back(std::to_string(s));
  throw request_error("size", "expected one of " + join(names) + ", got " + shown(*it));
}

int read_clusters(const json& request) {
  const auto it = request.find("k");
  if (it == request.end()) return kDefaultClusters;
  if (!it->is_number_integer() || *it < 1 || *it > kMaxClusters)
    throw request_error(
        "k", "expected an integer in [1, " + std::to_string(kMaxClusters) + "], got " + shown(*it));
  return it->get<int>();
}

json model_json(const ModelInfo& info, const ParamGrid& grid) {
  json params = json::array();
  for (std::size_t d = 0; d < info.params.size(); ++d) {
    const ParamSpec& p = info.params[d];
    params.push_back({{"name", p.name},
                      {"unit", p.unit},
                      {"description", p.description},
                      {"valid", {p.valid_min, p.valid_max}},
                      {"default", p.default_value},
                      {"scale", p.scale == Scale::log ? "log" : "linear"},
                      {"grid", grid.axis(d)}});
  }
  return {{"name", info.name}, {"title", info.title}, {"params", params}};
}

// The database's provenance, as an export writes it, and its number of embedding components.
json database_json(const Database& db) {
  json info = provenance_json(db);
  info["components"] = db.manifest().components;
  return info;
}

// The request's display and view, or the config's defaults; each checked against the config.
std::pair<std::string, std::string> read_display_view(const ocio::ColorPipeline& color,
                                                      const json& request) {
  const std::string display = optional_string(request, "display").value_or(color.default_display());
  try {
    color.views(display);
  } catch (const ocio::ColorError& e) {
    throw request_error("display", e.what());
  }
  const std::string view = optional_string(request, "view").value_or(color.default_view(display));
  try {
    color.validate(display, view);
  } catch (const ocio::ColorError& e) {
    throw request_error("view", e.what());
  }
  return {display, view};
}

// The API's paths: /api/info is read with GET (httplib answers HEAD with the GET handler and
// drops the body), the others take a body with POST.
struct Route {
  std::string_view path;
  bool post;
  std::string_view allow() const { return post ? "POST" : "GET, HEAD"; }
  bool takes(std::string_view method) const {
    return post ? method == "POST" : method == "GET" || method == "HEAD";
  }
};
constexpr Route kRoutes[] = {{"/api/info", false},     {"/api/environment", false},
                             {"/api/neighbors", true}, {"/api/thumbnail", true},
                             {"/api/export", true},    {"/api/import", true}};

}  // namespace

NavigatorApi::NavigatorApi(const ApiOptions& options)
    : navigator_(Navigator::open(options.db)),
      thumbnails_(navigator_.database(), options.resolution),
      exact_(navigator_.database(), thumbnails_.resolution()),
      final_(thumbnails_, exact_, options.faithful_blend) {
  sizes_.push_back(thumbnails_.resolution());
  for (int size : kSharpThumbnailSizes)
    if (size > sizes_.front()) sizes_.push_back(size);
}

void NavigatorApi::release_memory() const {
  navigator_.release_pages();
  trim_heap();
}

ApiResponse NavigatorApi::handle(const ApiRequest& r) const {
  const auto route = std::find_if(std::begin(kRoutes), std::end(kRoutes),
                                  [&](const Route& route) { return route.path == r.path; });
  const std::string request = cut(std::string(r.method) + " " + std::string(r.path));
  if (route == std::end(kRoutes)) return error_response(404, request + ": not found");
  if (!route->takes(r.method)) return method_not_allowed(r.method, r.path, route->allow());
  if (r.path == "/api/info") return info();
  if (r.path == "/api/environment") {
    json display_view = json::object();
    for (const char* key : {"display", "view"})
      if (const auto it = r.query.find(key); it != r.query.end()) display_view[key] = it->second;
    return environment(display_view.dump());
  }
  if (r.body.size() > kMaxBodyBytes)
    return error_response(400, "body: larger than " + std::to_string(kMaxBodyBytes) + " bytes");
  if (r.path == "/api/neighbors") return neighbors(r.body);
  if (r.path == "/api/thumbnail") return thumbnail(r.body);
  if (r.path == "/api/export") return export_material(r.body);
  const auto name = r.query.find("name");
  return import_yaml(r.body, name == r.query.end() ? "" : name->second);
}

ApiResponse NavigatorApi::info() const {
  return answer([&] {
    const Database& db = navigator_.database();
    json models = json::array();
    for (const ModelInfo& m : brdfnav::models()) {
      const ModelEmbedding* embedding = db.embedding(m.id);
      if (!embedding) continue;
      models.push_back(model_json(m, embedding->grid()));
    }
    json tabs = json::array();
    for (Tab t : kTabs) tabs.push_back(tab_name(t));
    json displays = json::array();
    for (const std::string& d : color_.displays())
      displays.push_back({{"name", d}, {"views", color_.views(d)}});
    return json_response(
        {{"models", models},
         {"tabs", tabs},
         {"displays", displays},
         {"colour_config", color_.describe()},
         {"radius", {{"min", kSliderMin}, {"max", kSliderMax}, {"start", kSliderStart}}},
         {"start", material_json(navigator_.start_material())},
         {"thumbnail_resolution", thumbnails_.resolution()},
         {"thumbnail_sizes", sizes_},
         {"max_body_bytes", kMaxBodyBytes},
         {"database", database_json(db)}});
  });
}

ApiResponse NavigatorApi::environment(std::string_view body) const {
  return answer([&] {
    const json request = parse_body(body, {"display", "view"});
    const auto [display, view] = read_display_view(color_, request);
    const ocio::Thumbnail shown = display_encode(exact_.environment_picture(kEnvironmentPicture),
                                                 false, color_, display, view);
    return ApiResponse{200, "image/png", encode_png(shown.rgba, shown.width, shown.height), {}};
  });
}

ApiResponse NavigatorApi::neighbors(std::string_view body) const {
  return answer([&] {
    const json request = parse_body(body, {"material", "radius", "tab", "k", "exact", "ring"});
    const Material current = read_material(navigator_.database(), require(request, "material"));
    const double radius = read_radius(require(request, "radius"));
    const Tab tab = read_tab(require(request, "tab"));
    std::function<void()> before_render = enter_ring(rings_, request);
    std::optional<ExactSteps> steps;
    if (read_flag(request, "exact"))
      steps = final_.steps_from(current, radius, std::move(before_render));
    json list = json::array();
    for (const Neighbor& n : navigator_.neighbors(current, radius, tab, read_clusters(request),
                                                  steps ? &*steps : nullptr))
      list.push_back(json(neighbor_json(n)));
    return json_response({{"neighbors", list}});
  });
}

ApiResponse NavigatorApi::thumbnail(std::string_view body) const {
  return answer([&] {
    const json request =
        parse_body(body, {"material", "display", "view", "preview", "size", "ring"});
    const Material m = read_material(navigator_.database(), require(request, "material"));
    const auto [display, view] = read_display_view(color_, request);
    const bool quick = read_flag(request, "preview");
    const int size = read_size(request, sizes_);
    if (quick && size != thumbnails_.resolution())
      throw request_error(
          "size", "a preview is drawn at " + std::to_string(thumbnails_.resolution()) + " px only");
    const std::function<void()> before_render = enter_ring(rings_, request);
    const bool blend = quick || final_.shows_blend(m, size);
    // A copy of a cached exact render: the display encoding works in place.
    Image linear = blend ? thumbnails_.render(m) : Image(*exact_.render(m, size, before_render));
    const ocio::Thumbnail shown = display_encode(
        std::move(linear), shows_sphere(navigator_.database()), color_, display, view);
    return ApiResponse{200,
                       "image/png",
                       encode_png(shown.rgba, shown.width, shown.height),
                       {{"X-Brdfnav-Image", blend ? "blend" : "render"}}};
  });
}

ApiResponse NavigatorApi::export_material(std::string_view body) const {
  return answer([&] {
    const json request = parse_body(body, {"material", "format"});
    const Material m = read_material(navigator_.database(), require(request, "material"));
    lookdev::ExportFormat format = lookdev::ExportFormat::yaml;
    if (const std::optional<std::string> name = optional_string(request, "format")) {
      try {
        format = lookdev::parse_export_format(*name);
      } catch (const Error&) {  // its own message quotes the name unescaped
        throw request_error("format", "expected one of yaml, materialx, cycles, got " +
                                          shown(request.at("format")));
      }
    }
    // The renderers' formats render the material and its ggx form to state their distance: at
    // the database's resolution, at most kExportResolution, so that the button answers in
    // seconds.
    const int resolution = std::min(navigator_.database().manifest().resolution, kExportResolution);
    return ApiResponse{200,
                       std::string(lookdev::export_content_type(format)),
                       lookdev::export_document(navigator_, m, format, resolution),
                       {}};
  });
}

ApiResponse NavigatorApi::import_yaml(std::string_view body, std::string_view name) const {
  return answer([&] {
    const std::string source = name.empty() ? "upload" : cut(std::string(name));
    const Material m = check_held(navigator_.database(), parse_material_yaml(body, source));
    return json_response({{"material", material_json(m)}});
  });
}

}  // namespace brdfnav::serve
