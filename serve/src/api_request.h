// What every route of `brdfnav serve`'s API shares (serve_api.cpp, lightings.cpp): reading a
// request's JSON body and its fields with errors that name the field, the answers' JSON and PNG
// bodies, and the HTTP status of an error. Internal to serve/.
#pragma once

#include <brdfnav/core/error.h>
#include <brdfnav/core/material.h>
#include <brdfnav/navigator/database.h>
#include <brdfnav/serve/serve_api.h>
#include <brdfnav/serve/serve_rings.h>

#include <nlohmann/json.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace brdfnav::serve {

using nlohmann::json;

// A request the API cannot answer: the client's mistake, its message starting with the field at
// fault.
Error request_error(const std::string& field, const std::string& what);

// Invalid UTF-8, which an uploaded file may carry into a message or a name, becomes U+FFFD
// rather than an exception.
std::string json_text(const json& value);

ApiResponse json_response(const json& body);

std::string join(const std::vector<std::string>& names);

// Text as an error message quotes it: cut to 80 characters, so that a 64 KiB value, field name
// or file name does not come back whole.
std::string cut(std::string text);

// The request body as a JSON object with only the `allowed` keys.
json parse_body(std::string_view body, const std::vector<std::string>& allowed);

// Whether `value` nests more than `levels` arrays or objects; looks no deeper than that, so a
// hostile body cannot make this, or the recursive dump(), run out of stack.
bool deeper_than(const json& value, int levels);

// A value as an error message quotes it: cut, and not dumped at all when nested deeply.
std::string shown(const json& value);

const json& require(const json& request, const std::string& field);

std::optional<std::string> optional_string(const json& request, const std::string& field);

// Every query needs the material's model in the database.
Material check_held(const Database& db, Material m);

// JSON is YAML's flow syntax, so the material reader of the YAML files reads a JSON material
// as it is, with the same checks and messages ("material:1: params.n: ..."), once it holds no
// key too long for YAML (no material key is).
Material read_material(const Database& db, const json& value);

// 8-bit RGBA as a PNG file in memory: display_encode()'s, whose straight alpha is PNG's own
// convention, so that a browser composites the sphere's edge over whatever lies behind.
std::string encode_png(const std::vector<std::uint8_t>& rgba, int width, int height);

// 405 for `method` on `path`, with the Allow header naming the methods it takes.
ApiResponse method_not_allowed(std::string_view method, std::string_view path,
                               std::string_view allow);

// The HTTP status of an Error: the client's mistakes are 400, the server's failures 500.
int http_status(ErrorCode code);

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

}  // namespace brdfnav::serve
