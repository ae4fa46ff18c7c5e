#pragma once
#include <OpenColorIO/OpenColorIO.h>

namespace brdfnav::ocio {

// The config used when $OCIO is not set, assembled from OCIO 2.1's built-in transforms (2.1 has no
// ocio:// configs): scene reference ACES2065-1, display reference CIE XYZ D65. Validated.
OCIO_NAMESPACE::ConstConfigRcPtr make_builtin_config();

}  // namespace brdfnav::ocio
