// The scene of a BRDF image: a unit sphere or a triangle mesh, ray cast with Embree 3, seen by an
// orthographic camera on +z looking toward -z (y up) whose square image spans [-1, 1]^2.
#pragma once

#include <brdfnav/core/error.h>
#include <brdfnav/core/math.h>

#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace brdfnav {

// A scene that cannot be built (missing or malformed OBJ, Embree failure); names the file.
using SceneError = LayerError<struct SceneErrorTag, ErrorCode::io>;

// What the camera sees at one pixel centre.
struct SurfacePoint {
  bool covered = false;
  Vec3 position{0, 0, 0};
  Vec3 normal{0, 0, 1};            // shading normal, unit, on the camera's side of the surface
  Vec3 geometric_normal{0, 0, 1};  // unit, on the camera's side
};

// One primary ray per pixel centre, row 0 at the top of the image (y = +1).
struct SurfaceBuffer {
  int resolution = 0;
  std::vector<SurfacePoint> points;  // resolution^2, row-major
  const SurfacePoint& at(int x, int y) const {
    return points[static_cast<std::size_t>(y) * resolution + x];
  }
};

// Direction from the surface toward the orthographic camera.
inline const Vec3 kViewDirection{0, 0, 1};

class Scene {
 public:
  // The unit sphere at the origin (an Embree sphere primitive; normals are recomputed in double
  // from the hit point, so they are exact).
  static Scene sphere();
  // A triangle mesh from an OBJ file (all shapes, faces triangulated), centred on its bounding
  // box and scaled so that its farthest vertex lies on the unit sphere, i.e. framed like the
  // sphere. Vertex normals are interpolated when every face has them, else faces are flat.
  // Surfaces are two-sided. Throws SceneError naming the file.
  static Scene load_obj(const std::filesystem::path& path);
  // The scene a description() names: "sphere", else an OBJ path (what --scene takes and a
  // manifest records).
  static Scene load(const std::string& description);

  Scene(Scene&&) noexcept;
  Scene& operator=(Scene&&) noexcept;
  ~Scene();

  // "sphere" or the OBJ path.
  const std::string& description() const;
  // True when no surface point can shadow another (the sphere): occlusion queries are skipped.
  bool convex() const;
  std::size_t triangle_count() const;

  SurfaceBuffer trace_camera(int resolution) const;
  // Whether the ray from the surface point `p` toward `direction` is blocked by the scene.
  bool occluded(const SurfacePoint& p, const Vec3& direction) const;

 private:
  struct Impl;
  explicit Scene(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace brdfnav
