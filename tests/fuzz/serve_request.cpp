// Fuzz target: a request to `brdfnav serve`'s API (NavigatorApi::handle, what the HTTP server
// calls) on the fixture database. The input is "METHOD PATH[?key=value&...]", a newline and the
// body; the query's values are taken as httplib would hand them over, already decoded.
//
// Every answer must be one the API documents (docs/SERVE.md): 200, 400 for the client's mistakes,
// 404 for an unknown path or 405 with an Allow header for a method the path does not take, never
// 500; JSON that parses, with an "error" string unless 200; a PNG for a thumbnail; an export
// that reads back as a material.
#include "fuzz_target.h"

#include <brdfnav/serve/serve_api.h>

#include <brdfnav/io/material_yaml.h>

#include <nlohmann/json.hpp>

#include <map>

namespace brdfnav::fuzz {
namespace {

const serve::NavigatorApi& api() {
  // The smallest thumbnails the server allows: the fuzzer is after the parsing, not the images.
  static const serve::NavigatorApi instance(serve::ApiOptions{BRDFNAV_FUZZ_DATABASE, 8});
  return instance;
}

std::multimap<std::string, std::string> parse_query(std::string_view text) {
  std::multimap<std::string, std::string> query;
  while (!text.empty()) {
    const std::string_view pair = text.substr(0, text.find('&'));
    text.remove_prefix(std::min(text.size(), pair.size() + 1));
    const std::size_t eq = pair.find('=');
    query.emplace(pair.substr(0, eq), eq == pair.npos ? "" : pair.substr(eq + 1));
  }
  return query;
}

void check_json(const serve::ApiResponse& answer) {
  if (!nlohmann::json::accept(answer.body)) fail("answer is not JSON: " + answer.body);
  const nlohmann::json body = nlohmann::json::parse(answer.body);
  if (answer.status != 200 && !(body.contains("error") && body["error"].is_string()))
    fail("error answer without an error message: " + answer.body);
}

void check(const serve::ApiResponse& answer) {
  if (answer.status != 200 && answer.status != 400 && answer.status != 404 && answer.status != 405)
    fail("status " + std::to_string(answer.status) + ": " + answer.body);
  if ((answer.status == 405) != (answer.headers.size() == 1 && answer.headers[0].first == "Allow"))
    fail("status " + std::to_string(answer.status) + " and an Allow header go together");
  if (answer.content_type == "application/json") {
    check_json(answer);
  } else if (answer.status != 200) {
    fail("error answer of type " + answer.content_type);
  } else if (answer.content_type == "image/png") {
    if (answer.body.rfind("\x89PNG\r\n\x1a\n", 0) != 0) fail("thumbnail is not a PNG");
  } else if (answer.content_type == "application/yaml") {
    try {
      parse_material_yaml(answer.body, "export.yaml");
    } catch (const MaterialError& e) {
      fail(std::string("the export does not read back: ") + e.what());
    }
  } else {
    fail("unexpected content type " + answer.content_type);
  }
}

}  // namespace
}  // namespace brdfnav::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace brdfnav;
  const std::string_view input = fuzz::as_text(data, size);
  const std::string_view line = input.substr(0, input.find('\n'));
  const std::string_view body = input.substr(std::min(input.size(), line.size() + 1));
  const std::string_view method = line.substr(0, line.find(' '));
  const std::string_view target = line.substr(std::min(line.size(), method.size() + 1));
  const std::string_view path = target.substr(0, target.find('?'));
  const auto query = fuzz::parse_query(target.substr(std::min(target.size(), path.size() + 1)));
  fuzz::check(fuzz::api().handle({method, path, query, body}));
  return 0;
}
