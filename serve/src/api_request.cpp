#include "api_request.h"

#include <brdfnav/io/material_yaml.h>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>

namespace brdfnav::serve {

namespace {

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

}  // namespace

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
  return {200, "application/json", json_text(body), {}};
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

ApiResponse method_not_allowed(std::string_view method, std::string_view path,
                               std::string_view allow) {
  ApiResponse refused =
      error_response(405, cut(std::string(method) + " " + std::string(path)) +
                              ": method not allowed (allowed: " + std::string(allow) + ")");
  refused.headers.emplace_back("Allow", allow);
  return refused;
}

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

ApiResponse error_response(int status, const std::string& message) {
  return {status, "application/json", json_text({{"error", message}}), {}};
}

}  // namespace brdfnav::serve
