// Several databases served at once, one per lighting (docs/SERVE.md, Lightings): what
// `brdfnav serve --db A --db B ...` answers. Each database keeps its own NavigatorApi
// (serve_api.h); a request names its lighting with the query parameter `lighting` (the first
// database's when absent), and a material carries over from one lighting to another.
#pragma once

#include <brdfnav/serve/serve_api.h>

#include <memory>
#include <string>
#include <vector>

namespace brdfnav::serve {

class LightingsApi {
 public:
  // Opens every database in order (an Error naming the directory when one does not open) and
  // names each lighting by its map's file stem ("forest"; "forest-2" for the second map of that
  // name). Error (invalid_argument) naming both directories for two databases of the same map
  // (its pixels), profile and resolution: the second would never be seen.
  explicit LightingsApi(const std::vector<ApiOptions>& databases);
  LightingsApi(const LightingsApi&) = delete;
  LightingsApi& operator=(const LightingsApi&) = delete;

  // GET /api/lightings -> {lightings: [{id, map (the file's name), path, profile, resolution,
  // models}], default}. POST /api/carry?lighting=TO {material, from} -> {material, carried}: the
  // material of lighting `from` in lighting TO, "same" (the same parameters, its model being in
  // both), "nearest" (its best fit among TO's models, with `residual`, the embedded distance in
  // `from`) or "start" (TO's start material: no model in common). Every other path goes to the
  // NavigatorApi of the request's `lighting`; an unknown one is 400 naming the lightings.
  ApiResponse handle(const ApiRequest& request) const;

  std::size_t size() const { return apis_.size(); }
  const NavigatorApi& api(std::size_t i) const { return *apis_[i]; }
  const std::string& id(std::size_t i) const { return ids_[i]; }

  // Every database's NavigatorApi::release_memory().
  void release_memory() const;

 private:
  ApiResponse lightings() const;
  ApiResponse carry(const ApiRequest& request) const;
  // The index of lighting `id`; Error (invalid_argument) naming `field` and the lightings when
  // there is none.
  std::size_t index_of(const std::string& id, const char* field) const;
  // The index of the request's `lighting` query parameter (0 when absent).
  std::size_t lighting_of(const ApiRequest& request) const;

  std::vector<std::unique_ptr<NavigatorApi>> apis_;
  std::vector<std::string> ids_;
};

}  // namespace brdfnav::serve
