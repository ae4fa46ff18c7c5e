#include <brdfnav/serve/serve_api.h>

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

using nlohmann::json;

// The page's radius slider: its range and start, in the metric's units (cube-root RMS), from
// where a step starts to show to about the distance between a matte and a glossy material. The
// navigator itself takes radii down to kMinRadius (the embedding's noise).
constexpr double kSliderMin = 0.002, kSliderMax = 0.2, kSliderStart = 0.03;
constexpr int kMaxClusters = 32;

// A request the API cannot answer: the client's mistake, its message starting with the field at
// fault.
Error request_error(const std::string& field, const std::string& what) {
  return Error(ErrorCode::invalid_argument, field, what);
}

// Invalid UTF-8, which an uploaded file may carry into a message or a name, becomes U+FFFD
// rather than an exception.
std::string json_text(const json& value) {
  return value.dump(-1, ' ', false, json::error_handler_t::replace);
}

ApiResponse json_response(const json& body) {
  return {200, "application/json", json_text(body)};
}

std::string join(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

// Text as an error message quotes it: cut to 80 characters, so that a 64 KiB value, field name
// or file name does not come back whole.
std::string cut(std::string text) {
  if (text.size() > 80) text = text.substr(0, 77) + "...";
  return text;
}

// The request body as a JSON object with only the `allowed` keys.
json parse_body(std::string_view body, const std::vector<std::string>& allowed) {
  json request;
  try {
    request = json::parse(body);
  } catch (const json::exception& e) {  // parse_error, and out_of_range for 1e999
    throw request_error("body", std::string("malformed JSON: ") + e.what());
  }
  if (!request.is_object()) throw request_error("body", "expected a JSON object");
  for (const auto& [key, value] : request.items())
    if (std::find(allowed.begin(), allowed.end(), key) == allowed.end())
      throw request_error(cut(key), "unknown field (expected one of: " + join(allowed) + ")");
  return request;
}

// Whether `value` nests more than `levels` arrays or objects; looks no deeper than that, so a
// hostile body cannot make this, or the recursive dump(), run out of stack.
bool deeper_than(const json& value, int levels) {
  if (!value.is_structured()) return false;
  if (levels == 0) return true;
  for (const json& child : value)
    if (deeper_than(child, levels - 1)) return true;
  return false;
}

// A value as an error message quotes it: cut, and not dumped at all when nested deeply.
std::string shown(const json& value) {
  if (deeper_than(value, 3)) return "a value nested too deeply";
  return cut(json_text(value));
}

const json& require(const json& request, const std::string& field) {
  const auto it = request.find(field);
  if (it == request.end()) throw request_error(field, "missing");
  return *it;
}

std::optional<std::string> optional_string(const json& request, const std::string& field) {
  const auto it = request.find(field);
  if (it == request.end()) return std::nullopt;
  if (!it->is_string()) throw request_error(field, "expected a string, got " + shown(*it));
  return it->get<std::string>();
}

// Every query needs the material's model in the database.
Material check_held(const Database& db, Material m) {
  if (!db.embedding(m.model))
    throw request_error("material.model", "the database holds no model '" +
                                              std::string(model_info(m.model).name) + "'");
  return m;
}

// YAML limits an implicit key to 1024 characters of its text, quotes and escapes included;
// yaml-cpp fails a longer one as a syntax error (a key of 1023 bytes is 1025 characters quoted,
// a control character 6 escaped). Bytes are counted, which is stricter for UTF-8.
constexpr std::size_t kMaxYamlKeyText = 1024;

const std::string* overlong_key(const json& value) {
  if (!value.is_structured()) return nullptr;
  for (auto it = value.begin(); it != value.end(); ++it) {
    if (value.is_object() && json(it.key()).dump().size() > kMaxYamlKeyText) return &it.key();
    if (const std::string* key = overlong_key(*it)) return key;
  }
  return nullptr;
}

// JSON is YAML's flow syntax, so the material reader of the YAML files reads a JSON material
// as it is, with the same checks and messages ("material:1: params.n: ..."), once it holds no
// key too long for YAML (no material key is).
Material read_material(const Database& db, const json& value) {
  if (!value.is_object())
    throw request_error("material", "expected an object, got " + shown(value));
  if (deeper_than(value, 3)) throw request_error("material", "nested too deeply");
  if (const std::string* key = overlong_key(value))
    throw request_error("material", "unknown key of " + std::to_string(key->size()) + " bytes " +
                                        shown(json(*key)));
  return check_held(db, material_from_node(YAML::Load(value.dump()), "material", false));
}

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

// 8-bit RGBA as a PNG file in memory: display_encode()'s, whose straight alpha is PNG's own
// convention, so that a browser composites the sphere's edge over whatever lies behind.
std::string encode_png(const std::vector<std::uint8_t>& rgba, int width, int height) {
  std::vector<unsigned char> bytes;
  OIIO::Filesystem::IOVecOutput proxy(bytes);
  const char* name = "thumbnail.png";  // chooses the format; nothing is written to disk
  std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(name);
  OIIO::ImageSpec spec(width, height, 4, OIIO::TypeDesc::UINT8);
  // zlib's fastest level: at the default (6) deflating took a third of a loaded server's CPU
  // (8 pages at once); level 1 makes a thumbnail 1.4 times the bytes (19 KB instead of 15 at
  // 128 px).
  spec.attribute("png:compressionLevel", 1);
  if (!out || !out->set_ioproxy(&proxy) || !out->open(name, spec) ||
      !out->write_image(OIIO::TypeDesc::UINT8, rgba.data()) || !out->close())
    throw std::runtime_error("cannot encode the thumbnail as PNG: " +
                             (out ? out->geterror() : OIIO::geterror()));
  return std::string(bytes.begin(), bytes.end());
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
constexpr Route kRoutes[] = {{"/api/info", false},
                             {"/api/neighbors", true},
                             {"/api/thumbnail", true},
                             {"/api/export", true},
                             {"/api/import", true}};

// The HTTP status of an Error: the client's mistakes are 400, the server's failures 500.
int http_status(ErrorCode code) {
  switch (code) {
    case ErrorCode::invalid_argument:
    case ErrorCode::parse:
      return 400;
    case ErrorCode::io:
    case ErrorCode::database:
    case ErrorCode::internal:
      return 500;
  }
  return 500;
}

// Runs `body`, answering an error with its status: http_status() of an Error, 409 for work of a
// ring the page has left, 500 for anything else.
template <typename Body>
ApiResponse answer(Body&& body) {
  try {
    return body();
  } catch (const Error& e) {
    return error_response(http_status(e.code()), e.what());
  } catch (const RingLeft& e) {
    return error_response(409, e.what());
  } catch (const std::exception& e) {
    return error_response(500, e.what());
  }
}

}  // namespace

ApiResponse error_response(int status, const std::string& message) {
  return {status, "application/json", json_text({{"error", message}})};
}

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
  if (!route->takes(r.method)) {
    ApiResponse refused = error_response(
        405, request + ": method not allowed (allowed: " + std::string(route->allow()) + ")");
    refused.headers.emplace_back("Allow", route->allow());
    return refused;
  }
  if (r.path == "/api/info") return info();
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
    return ApiResponse{200, std::string(lookdev::export_content_type(format)),
                       lookdev::export_document(navigator_, m, format, resolution)};
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
