// The blend a thumbnail shows between grid nodes (brdfnav/navigator/thumbnails.h), as a function
// of images: the one definition the navigator's thumbnails and the builder's blend check
// (db::blend_check_file(), docs/DATABASE.md) share.
#pragma once

#include <brdfnav/core/grid.h>
#include <brdfnav/core/image.h>
#include <brdfnav/core/material.h>

#include <span>

namespace brdfnav {

// The specular image of each of `corners` (`specular`, in the same order) composed with `rho_d`
// times `diffuse` and `rho_s`, summed with the corners' weights in cube-root space, clamped at 0
// and cubed back; alpha is `diffuse`'s mask, and the pixels it leaves uncovered are black. Throws
// ImageError when the images' sizes differ, std::invalid_argument when there is not one image per
// corner.
Image blend_images(const Image& diffuse, std::span<const ParamGrid::Corner> corners,
                   std::span<const Image* const> specular, const Rgb& rho_d, const Rgb& rho_s);

}  // namespace brdfnav
