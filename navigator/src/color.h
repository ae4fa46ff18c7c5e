// The colour tabs (paper, section 3.3): CIELAB directions around rho_d or rho_s, each walked to
// the embedded distance eps inside the valid range of the colour.
#pragma once

#include "walk.h"

#include <brdfnav/core/math.h>

namespace brdfnav::nav {

enum class ColorTerm { diffuse, specular };

// Ten rays from the current colour of `term` in CIELAB: "L+", "L-" and the a-b plane every 45
// degrees from +a ("ab+0" ... "ab+315"). Each ends where the colour leaves its valid range
// (rho_d in [0, kRhoDMax], rho_s in [0, kRhoSMax]); the material must be lin_rec709.
std::vector<Path> color_paths(const Material& m, ColorTerm term);

}  // namespace brdfnav::nav
