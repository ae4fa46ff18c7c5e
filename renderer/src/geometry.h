// Small direction helpers of the renderer.
#pragma once

#include <brdfnav/core/math.h>

// cross() (used here and by Frame::from_normal_tangent in math.h) lives in Eigen/Geometry.
#include <Eigen/Geometry>

namespace brdfnav {

// Angle between two unit vectors, accurate for tiny and for near-opposite pairs.
inline double angle_between(const Vec3& a, const Vec3& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

}  // namespace brdfnav
