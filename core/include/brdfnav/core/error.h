// brdfnav's one error type. Every layer throws an Error: its message names what is at fault (the
// file, line, key or argument) and its code says what kind of failure it is. Each edge maps the
// code once, whatever layer threw: the C ABI onto brdfnav_status (plugin/src/c_abi.cpp), the CLI
// onto its exit codes (app/main.cpp), the HTTP API onto status codes (serve/src/serve_api.cpp).
//
// The layers' own names (MaterialError, DatabaseError, ...) are Errors with a default code, so a
// caller can still catch one layer's failures alone. A layer re-throws another layer's error as
// its own kind only where the failure means something else at its level, and says so there:
// - what is read inside a database (an image, an image header's material, the manifest's text or
//   its render quality) fails as a DatabaseError: the database is damaged (navigator/src/
//   database.cpp, database_format.cpp, thumbnails.cpp; lookdev's exact_thumbnails.cpp);
// - a material file that cannot be read is a MaterialError with ErrorCode::io, and a bad value
//   in it is reported at its line and key (plugin/src/material_yaml.cpp);
// - a material a host hands the C ABI as a struct is the caller's argument: invalid_argument
//   (plugin/src/c_abi.cpp);
// - the map a build recorded that no longer loads is an EnvMapError with ErrorCode::database
//   (renderer/src/env_map.cpp, load_recorded_env).
// Everywhere else an error passes through as it was thrown.
#pragma once

#include <stdexcept>
#include <string>

namespace brdfnav {

enum class ErrorCode {
  // The caller's mistake: a value out of range, a name that is not known, a null pointer.
  invalid_argument,
  // Malformed text: an inline material spec, a material or profile file, a request body.
  parse,
  // A file or an environment that cannot be read or written: missing, unreadable, no space, an
  // OCIO config that does not load, an image whose pixels are not what its header says.
  io,
  // A navigation database that is missing, corrupt or inconsistent, or whose map has changed.
  database,
  // A failure inside brdfnav: a bug.
  internal,
};

class Error : public std::runtime_error {
 public:
  Error(ErrorCode code, const std::string& message) : std::runtime_error(message), code_(code) {}
  // what() is "context: detail"; context() is the file, key or argument at fault.
  Error(ErrorCode code, const std::string& context, const std::string& detail)
      : std::runtime_error(context + ": " + detail), code_(code), context_(context) {}

  ErrorCode code() const noexcept { return code_; }
  // What the error was raised about when the thrower named it apart from the message (a request's
  // field, an argument's name); empty when it is only in the message.
  const std::string& context() const noexcept { return context_; }

 private:
  ErrorCode code_;
  std::string context_;
};

// Runs `body`; an Error it throws comes out as "context: what()" with its code kept (an option or
// a file the failure was about). The layer's own type (DatabaseError, ...) is not kept.
template <typename Body>
auto with_context(const std::string& context, Body&& body) -> decltype(body()) {
  try {
    return body();
  } catch (const Error& e) {
    throw Error(e.code(), context, e.what());
  }
}

// A layer's own kind of Error (one type per `Tag`), thrown with `kDefault` unless the thrower
// knows better: a material file that cannot be read is a MaterialError with ErrorCode::io.
template <typename Tag, ErrorCode kDefault>
class LayerError : public Error {
 public:
  explicit LayerError(const std::string& message, ErrorCode code = kDefault)
      : Error(code, message) {}
};

}  // namespace brdfnav
