#include <brdfnav/renderer/scene.h>

#include <embree3/rtcore.h>
#include <tiny_obj_loader.h>

#include <array>
#include <limits>
#include <mutex>

namespace brdfnav {

// A named namespace, not an anonymous one: Scene::Impl holds these types, and gcc warns
// (-Wsubobject-linkage) when a class defined outside the main file holds types of an anonymous
// namespace, which a unity build makes of every source.
namespace scene_parts {

// Owns an Embree device whose error callback records the first error; callers check() after
// each group of Embree calls, so no exception ever crosses Embree's frames.
class EmbreeDevice {
 public:
  EmbreeDevice() : device_(rtcNewDevice(nullptr)) {
    if (!device_)
      throw SceneError("Embree: cannot create a device (error " +
                       std::to_string(rtcGetDeviceError(nullptr)) + ")");
    rtcSetDeviceErrorFunction(device_, &EmbreeDevice::on_error, this);
  }
  ~EmbreeDevice() { rtcReleaseDevice(device_); }
  EmbreeDevice(const EmbreeDevice&) = delete;
  EmbreeDevice& operator=(const EmbreeDevice&) = delete;

  RTCDevice get() const { return device_; }
  void check(const std::string& what) const {
    std::lock_guard lock(mutex_);
    if (!error_.empty()) throw SceneError(what + ": Embree: " + error_);
  }

 private:
  static void on_error(void* self, RTCError code, const char* message) {
    auto* device = static_cast<EmbreeDevice*>(self);
    std::lock_guard lock(device->mutex_);
    if (device->error_.empty())
      device->error_ = (message ? std::string(message) : "error") + " (code " +
                       std::to_string(static_cast<int>(code)) + ")";
  }

  RTCDevice device_;
  mutable std::mutex mutex_;
  std::string error_;
};

class EmbreeScene {
 public:
  explicit EmbreeScene(RTCDevice device) : scene_(rtcNewScene(device)) {}
  ~EmbreeScene() {
    if (scene_) rtcReleaseScene(scene_);
  }
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;
  RTCScene get() const { return scene_; }

 private:
  RTCScene scene_;
};

struct Mesh {
  std::vector<Vec3> positions;                 // normalised to the unit sphere
  std::vector<std::array<unsigned, 3>> faces;  // into positions
  std::vector<std::array<Vec3, 3>> normals;    // per face corner; empty when faces are flat
};

}  // namespace scene_parts

using scene_parts::EmbreeDevice;
using scene_parts::EmbreeScene;
using scene_parts::Mesh;

struct Scene::Impl {
  EmbreeDevice device;
  EmbreeScene scene{device.get()};
  std::string description;
  bool convex = false;
  Mesh mesh;

  SurfacePoint surface(const RTCRayHit& rh, const Vec3& origin, const Vec3& dir) const;
};

namespace {

void attach_sphere(RTCDevice device, RTCScene scene) {
  RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_SPHERE_POINT);
  auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0,
                                                        RTC_FORMAT_FLOAT4, 4 * sizeof(float), 1));
  if (v) v[0] = v[1] = v[2] = 0.f, v[3] = 1.f;
  rtcCommitGeometry(geom);
  rtcAttachGeometry(scene, geom);
  rtcReleaseGeometry(geom);
}

void attach_mesh(RTCDevice device, RTCScene scene, const Mesh& mesh) {
  RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
  auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0,
                                                        RTC_FORMAT_FLOAT3, 3 * sizeof(float),
                                                        mesh.positions.size()));
  auto* f = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
      geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), mesh.faces.size()));
  if (v && f) {
    for (std::size_t i = 0; i < mesh.positions.size(); ++i)
      for (int c = 0; c < 3; ++c) v[3 * i + c] = static_cast<float>(mesh.positions[i][c]);
    for (std::size_t i = 0; i < mesh.faces.size(); ++i)
      for (int c = 0; c < 3; ++c) f[3 * i + c] = mesh.faces[i][c];
  }
  rtcCommitGeometry(geom);
  rtcAttachGeometry(scene, geom);
  rtcReleaseGeometry(geom);
}

std::string face_error(const std::string& file, std::size_t face, const char* what) {
  return file + ": face " + std::to_string(face + 1) + " references a " + what +
         " that does not exist";
}

// Reads the OBJ into positions and faces (with corner normals when all faces have them).
Mesh read_obj(const std::filesystem::path& path) {
  const std::string name = path.string();
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw SceneError(name + ": no such file");
  if (std::filesystem::is_directory(path, ec)) throw SceneError(name + ": is a directory");
  tinyobj::attrib_t attrib;
  std::vector<tinyobj::shape_t> shapes;
  std::vector<tinyobj::material_t> materials;
  std::string warn, err;
  const std::string dir = path.parent_path().string();
  if (!tinyobj::LoadObj(&attrib, &shapes, &materials, &warn, &err, name.c_str(),
                        dir.empty() ? nullptr : dir.c_str(), true))
    throw SceneError(name + ": cannot read OBJ: " + (err.empty() ? "unknown error" : err));
  Mesh mesh;
  for (std::size_t i = 0; i + 2 < attrib.vertices.size(); i += 3) {
    const Vec3 p(attrib.vertices[i], attrib.vertices[i + 1], attrib.vertices[i + 2]);
    if (!p.allFinite())
      throw SceneError(name + ": vertex " + std::to_string(i / 3 + 1) + " is not finite");
    mesh.positions.push_back(p);
  }
  bool all_normals = true;
  std::vector<std::array<int, 3>> corner_normals;
  for (const tinyobj::shape_t& shape : shapes) {
    for (std::size_t i = 0; i + 2 < shape.mesh.indices.size(); i += 3) {
      std::array<unsigned, 3> face;
      std::array<int, 3> normal;
      for (int c = 0; c < 3; ++c) {
        const tinyobj::index_t& idx = shape.mesh.indices[i + c];
        if (idx.vertex_index < 0 || std::size_t(idx.vertex_index) >= mesh.positions.size())
          throw SceneError(face_error(name, mesh.faces.size(), "vertex"));
        if (idx.normal_index >= 0 && std::size_t(3 * idx.normal_index + 2) >= attrib.normals.size())
          throw SceneError(face_error(name, mesh.faces.size(), "normal"));
        face[c] = static_cast<unsigned>(idx.vertex_index);
        normal[c] = idx.normal_index;
        all_normals = all_normals && idx.normal_index >= 0;
      }
      mesh.faces.push_back(face);
      corner_normals.push_back(normal);
    }
  }
  if (mesh.faces.empty()) throw SceneError(name + ": contains no faces");
  if (all_normals) {
    for (const auto& corner : corner_normals) {
      std::array<Vec3, 3> n;
      for (int c = 0; c < 3; ++c) {
        const float* a = &attrib.normals[3 * static_cast<std::size_t>(corner[c])];
        n[c] = Vec3(a[0], a[1], a[2]);
      }
      mesh.normals.push_back(n);
    }
  }
  return mesh;
}

// Centre on the bounding box, scale the farthest vertex onto the unit sphere.
void frame_mesh(Mesh& mesh, const std::string& name) {
  Vec3 lo = mesh.positions.front(), hi = lo;
  for (const Vec3& p : mesh.positions) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  const Vec3 centre = 0.5 * (lo + hi);
  double radius = 0;
  for (const Vec3& p : mesh.positions) radius = std::max(radius, (p - centre).norm());
  if (!(radius > 0)) throw SceneError(name + ": all vertices coincide");
  for (Vec3& p : mesh.positions) p = (p - centre) / radius;
}

}  // namespace

SurfacePoint Scene::Impl::surface(const RTCRayHit& rh, const Vec3& origin, const Vec3& dir) const {
  SurfacePoint s;
  s.covered = true;
  double t = rh.ray.tfar;
  if (mesh.faces.empty()) {
    // One Newton step on |o + t d|^2 = 1 brings Embree's float distance to double precision.
    const Vec3 p = origin + t * dir;
    t -= (p.squaredNorm() - 1) / (2 * dir.dot(p));
    s.position = (origin + t * dir).normalized();
    s.normal = s.geometric_normal = s.position;
    return s;
  }
  s.position = origin + t * dir;
  Vec3 ng = Vec3(rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z).normalized();
  if (ng.dot(-dir) < 0) ng = -ng;
  s.geometric_normal = ng;
  s.normal = ng;
  if (!mesh.normals.empty()) {
    const auto& n = mesh.normals[rh.hit.primID];
    const double u = rh.hit.u, v = rh.hit.v;
    const Vec3 shading = (1 - u - v) * n[0] + u * n[1] + v * n[2];
    if (shading.squaredNorm() > 0) s.normal = shading.normalized();
    if (s.normal.dot(ng) < 0) s.normal = -s.normal;
  }
  return s;
}

Scene::Scene(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Scene::Scene(Scene&&) noexcept = default;
Scene& Scene::operator=(Scene&&) noexcept = default;
Scene::~Scene() = default;

Scene Scene::sphere() {
  auto impl = std::make_unique<Impl>();
  impl->description = "sphere";
  impl->convex = true;
  attach_sphere(impl->device.get(), impl->scene.get());
  rtcCommitScene(impl->scene.get());
  impl->device.check("sphere");
  return Scene(std::move(impl));
}

Scene Scene::load(const std::string& description) {
  return description == "sphere" ? sphere() : load_obj(description);
}

Scene Scene::load_obj(const std::filesystem::path& path) {
  auto impl = std::make_unique<Impl>();
  impl->description = path.string();
  impl->mesh = read_obj(path);
  frame_mesh(impl->mesh, impl->description);
  attach_mesh(impl->device.get(), impl->scene.get(), impl->mesh);
  rtcCommitScene(impl->scene.get());
  impl->device.check(impl->description);
  return Scene(std::move(impl));
}

const std::string& Scene::description() const {
  return impl_->description;
}
bool Scene::convex() const {
  return impl_->convex;
}
std::size_t Scene::triangle_count() const {
  return impl_->mesh.faces.size();
}

SurfaceBuffer Scene::trace_camera(int resolution) const {
  SurfaceBuffer buffer;
  buffer.resolution = resolution;
  buffer.points.resize(static_cast<std::size_t>(resolution) * resolution);
  const Vec3 dir = -kViewDirection;
  for (int y = 0; y < resolution; ++y) {
    for (int x = 0; x < resolution; ++x) {
      const Vec3 origin(-1 + (x + 0.5) * 2 / resolution, 1 - (y + 0.5) * 2 / resolution, 4);
      RTCIntersectContext context;
      rtcInitIntersectContext(&context);
      RTCRayHit rh{};
      rh.ray.org_x = static_cast<float>(origin.x());
      rh.ray.org_y = static_cast<float>(origin.y());
      rh.ray.org_z = static_cast<float>(origin.z());
      rh.ray.dir_x = static_cast<float>(dir.x());
      rh.ray.dir_y = static_cast<float>(dir.y());
      rh.ray.dir_z = static_cast<float>(dir.z());
      rh.ray.tnear = 0.f;
      rh.ray.tfar = std::numeric_limits<float>::infinity();
      rh.ray.mask = ~0u;
      rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
      rtcIntersect1(impl_->scene.get(), &context, &rh);
      if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) continue;
      buffer.points[static_cast<std::size_t>(y) * resolution + x] = impl_->surface(rh, origin, dir);
    }
  }
  impl_->device.check(impl_->description);
  return buffer;
}

bool Scene::occluded(const SurfacePoint& p, const Vec3& direction) const {
  if (impl_->convex) return false;
  // Leave the surface on the side the ray goes to, far enough for float triangles.
  const double side = p.geometric_normal.dot(direction) >= 0 ? 1.0 : -1.0;
  const Vec3 origin = p.position + side * 1e-4 * p.geometric_normal;
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay ray{};
  ray.org_x = static_cast<float>(origin.x());
  ray.org_y = static_cast<float>(origin.y());
  ray.org_z = static_cast<float>(origin.z());
  ray.dir_x = static_cast<float>(direction.x());
  ray.dir_y = static_cast<float>(direction.y());
  ray.dir_z = static_cast<float>(direction.z());
  ray.tnear = 0.f;
  ray.tfar = std::numeric_limits<float>::infinity();
  ray.mask = ~0u;
  rtcOccluded1(impl_->scene.get(), &context, &ray);
  return ray.tfar < 0;
}

}  // namespace brdfnav
