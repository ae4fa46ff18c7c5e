// The JSON API of `brdfnav serve` (docs/SERVE.md) over the neighbour service, the thumbnails
// and the colour pipeline, kept apart from the HTTP server so that every answer, good or bad,
// is a plain value: a status, a content type and a body.
#pragma once

#include <brdfnav/lookdev/exact_thumbnails.h>
#include <brdfnav/lookdev/final_images.h>
#include <brdfnav/serve/serve_rings.h>

#include <brdfnav/navigator/navigator.h>
#include <brdfnav/navigator/thumbnails.h>
#include <brdfnav/ocio/color_pipeline.h>

#include <cstddef>
#include <filesystem>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace brdfnav::serve {

// The largest resolution at which the export for renderers renders the material and its ggx form
// to state their distance (the database's, if smaller).
inline constexpr int kExportResolution = 64;

// The largest request body the API reads; a material or an export is a few kilobytes.
inline constexpr std::size_t kMaxBodyBytes = 64 * 1024;
// The largest body the server still reads to the end to refuse it with the API's 400: httplib
// refuses a longer one from its Content-Length and closes the connection, which resets a client
// still sending it (fetch then fails instead of reading the 400).
inline constexpr std::size_t kDrainedBodyBytes = 16 * kMaxBodyBytes;

// Sizes of an exact thumbnail beside the thumbnails' resolution, for a large image on a screen
// of high pixel density (the page's centre: 256 CSS pixels, 512 device pixels at a ratio of 2).
inline constexpr int kSharpThumbnailSizes[] = {256, 512};

// The width of the picture of the database's map (GET /api/environment).
inline constexpr int kEnvironmentPicture = 256;

struct ApiResponse {
  int status = 200;
  std::string content_type;
  std::string body;
  std::vector<std::pair<std::string, std::string>> headers;  // beside Content-Type (Allow)
};

// {"error": message} with status 400 (the client's mistake), 404 (no such path), 405 (a method
// the path does not take) or 500 (the server's).
ApiResponse error_response(int status, const std::string& message);

// A request as the HTTP server decoded it. `query` holds the decoded parameters (httplib's
// Params); the body is as received.
struct ApiRequest {
  std::string_view method, path;
  const std::multimap<std::string, std::string>& query;
  std::string_view body;
};

struct ApiOptions {
  std::filesystem::path db;
  int resolution = 128;  // thumbnail width and height
  // The bar of the database's blend check under which a final image is a blend
  // (lookdev::FinalImages).
  double faithful_blend = lookdev::FinalImages::kFaithfulBlend;
};

// Opens the database, the thumbnails and the colour pipeline once; every method is const and
// may be called from any number of threads at once, as the three services allow. Requests that
// are malformed or ask for something the database or the colour config lacks get status 400
// with {"error": "<field>: <what is wrong>"}.
class NavigatorApi {
 public:
  explicit NavigatorApi(const ApiOptions& options);
  NavigatorApi(const NavigatorApi&) = delete;  // thumbnails_ refers into navigator_
  NavigatorApi& operator=(const NavigatorApi&) = delete;

  // Every route of the API: GET /api/info and the POSTs below. Any other path is 404
  // {"error": "<METHOD> <path>: not found"}; another method on one of these paths is 405 with
  // an Allow header; a body over kMaxBodyBytes is 400. What the server and the fuzzer of
  // tests/fuzz/serve_request.cpp call.
  ApiResponse handle(const ApiRequest& request) const;

  // GET /api/info: models and parameter tables, tabs, displays and views, radius range, the
  // start material and the database's provenance.
  ApiResponse info() const;
  // GET /api/environment[?display=D&view=V] -> image/png: the database's map, lat-long,
  // kEnvironmentPicture wide, exposed to a mean of mid grey (lookdev::ExactThumbnails::
  // environment_picture), through the display and view (the config's defaults when absent).
  // `body`: {display, view}, both optional. 500 naming the map when it no longer loads.
  ApiResponse environment(std::string_view body) const;
  // POST /api/neighbors {material, radius, tab[, k, exact, ring]} -> {neighbors: [{tab, label,
  // distance, flags, material}]}. With exact: true each offer moves until its final image
  // (lookdev::FinalImages: the render, or the blend where the database vouches for it) is at
  // `radius` from the material's (ExactSteps, at the database's resolution), `distance` then the
  // measured one: slower (a few images per offer), and the ring's steps equal. `ring`
  // ({client, id}), here and in /api/thumbnail: once the same client asks for a later ring, the
  // renders still to start for this one are dropped and the answer is 409.
  ApiResponse neighbors(std::string_view body) const;
  // POST /api/thumbnail {material[, display, view, preview, size]} -> image/png: the final
  // image of the material (lookdev::FinalImages: the exact render, or the blend where the
  // database's blend check vouches for it) at `size` (the thumbnails' resolution, or one of
  // kSharpThumbnailSizes above it: /api/info's thumbnail_sizes), or with preview: true the quick
  // blend of the database's images (Thumbnails) at the thumbnails' resolution, vouched for or
  // not. The header X-Brdfnav-Image says which: "blend" or "render". Alpha is the coverage, the
  // sphere's edge antialiased.
  ApiResponse thumbnail(std::string_view body) const;
  // POST /api/export {material[, format]} -> what `brdfnav export --format FORMAT` writes
  // (yaml, the default: application/yaml; materialx: application/xml; cycles:
  // application/json), the renderers' formats measured at kExportResolution at most.
  ApiResponse export_material(std::string_view body) const;
  // POST /api/import[?name=FILE] (a material YAML file, or an export) -> {material}; errors
  // name FILE (default "upload") and the line.
  ApiResponse import_yaml(std::string_view body, std::string_view name) const;

  // Returns to the system what only queries in flight need: the embeddings' mapped pages
  // (Navigator::release_pages) and the heap the allocator keeps free (trim_heap). The caches
  // of images stay. For a server with nothing to answer (IdleRelease).
  void release_memory() const;

  const Navigator& navigator() const { return navigator_; }

 private:
  Navigator navigator_;
  Thumbnails thumbnails_;
  // The exact thumbnails at every size, and the renders of exact steps at the database's
  // resolution (the metric's).
  lookdev::ExactThumbnails exact_;
  lookdev::FinalImages final_;  // what the page keeps: exact_'s renders or thumbnails_' blends
  std::vector<int> sizes_;      // of a thumbnail: the thumbnails' resolution first
  mutable LeftRings rings_;
  ocio::ColorPipeline color_;
};

}  // namespace brdfnav::serve
