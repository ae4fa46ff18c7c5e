// The navigator's page (serve/web/), compiled into the binary at build time by
// cmake/embed_web.cmake so that `brdfnav serve` needs no files beside it and fetches nothing from
// anywhere.
#pragma once

#include <span>
#include <string_view>

namespace brdfnav::serve {

struct WebAsset {
  std::string_view path;          // URL path: "/index.html", "/app.js", ...
  std::string_view content_type;  // from the file's extension
  std::string_view body;
};

std::span<const WebAsset> web_assets();

}  // namespace brdfnav::serve
