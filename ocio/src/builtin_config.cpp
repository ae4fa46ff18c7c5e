#include "builtin_config.h"

#include <brdfnav/ocio/color_pipeline.h>

#include <initializer_list>
#include <utility>

namespace brdfnav::ocio {

namespace OCIO = OCIO_NAMESPACE;

namespace {

// OCIO 2.1 BuiltinTransformRegistry styles, as the installed registry lists them. setStyle throws
// for a style the registry lacks, so every construction of this config re-checks them.
constexpr const char* kAcesCgToAp0 = "ACEScg_to_ACES2065-1";
constexpr const char* kAp1ToRec709 = "UTILITY - ACES-AP1_to_LINEAR-REC709_BFD";
constexpr const char* kAp0ToXyz = "UTILITY - ACES-AP0_to_CIE-XYZ-D65_BFD";
constexpr const char* kAcesSdrVideo = "ACES-OUTPUT - ACES2065-1_to_CIE-XYZ-D65 - SDR-VIDEO_1.0";
constexpr const char* kXyzToSRGB = "DISPLAY - CIE-XYZ-D65_to_sRGB";
constexpr const char* kXyzToRec1886 = "DISPLAY - CIE-XYZ-D65_to_REC.1886-REC.709";

constexpr const char* kAces2065 = "ACES2065-1";
constexpr const char* kAcesCg = "ACEScg";
constexpr const char* kXyzD65 = "CIE-XYZ-D65";
constexpr const char* kSRGBDisplaySpace = "sRGB - Display";
constexpr const char* kRec1886DisplaySpace = "Rec.1886 Rec.709 - Display";
constexpr const char* kUntonemapped = "Un-tone-mapped";
constexpr const char* kAcesViewTransform = "ACES 1.0 - SDR Video";

OCIO::BuiltinTransformRcPtr builtin(const char* style,
                                    OCIO::TransformDirection dir = OCIO::TRANSFORM_DIR_FORWARD) {
  auto t = OCIO::BuiltinTransform::Create();
  t->setStyle(style);
  t->setDirection(dir);
  return t;
}

OCIO::ColorSpaceRcPtr colorspace(OCIO::ReferenceSpaceType ref, const char* name, const char* family,
                                 const char* encoding, std::initializer_list<const char*> aliases) {
  auto cs = OCIO::ColorSpace::Create(ref);
  cs->setName(name);
  cs->setFamily(family);
  cs->setEncoding(encoding);
  for (const char* alias : aliases) cs->addAlias(alias);
  return cs;
}

void add_scene_spaces(OCIO::Config& config) {
  // The reference itself: no transform.
  config.addColorSpace(colorspace(OCIO::REFERENCE_SPACE_SCENE, kAces2065, "ACES", "scene-linear",
                                  {"lin_ap0", "aces2065_1"}));

  auto cg = colorspace(OCIO::REFERENCE_SPACE_SCENE, kAcesCg, "ACES", "scene-linear", {"lin_ap1"});
  cg->setTransform(builtin(kAcesCgToAp0), OCIO::COLORSPACE_DIR_TO_REFERENCE);
  config.addColorSpace(cg);

  // Linear Rec.709 reaches AP0 through AP1: the registry has AP1 -> Rec.709 but no Rec.709 -> AP0.
  auto rec709 = colorspace(OCIO::REFERENCE_SPACE_SCENE, kDefaultColorspace, "Scene-linear",
                           "scene-linear", {"Linear Rec.709 (sRGB)", "lin_srgb"});
  auto to_ap0 = OCIO::GroupTransform::Create();
  to_ap0->appendTransform(builtin(kAp1ToRec709, OCIO::TRANSFORM_DIR_INVERSE));
  to_ap0->appendTransform(builtin(kAcesCgToAp0));
  rec709->setTransform(to_ap0, OCIO::COLORSPACE_DIR_TO_REFERENCE);
  config.addColorSpace(rec709);
}

void add_display_spaces(OCIO::Config& config) {
  config.addColorSpace(
      colorspace(OCIO::REFERENCE_SPACE_DISPLAY, kXyzD65, "Display", "display-linear", {}));
  for (auto [name, style] :
       {std::pair{kSRGBDisplaySpace, kXyzToSRGB}, std::pair{kRec1886DisplaySpace, kXyzToRec1886}}) {
    auto cs = colorspace(OCIO::REFERENCE_SPACE_DISPLAY, name, "Display", "sdr-video", {});
    cs->setTransform(builtin(style), OCIO::COLORSPACE_DIR_FROM_REFERENCE);
    config.addColorSpace(cs);
  }
}

void add_view_transforms(OCIO::Config& config) {
  // "Standard": no tone mapping, only the change of reference (ACES AP0 -> XYZ D65); the display
  // colour space then applies the display's encoding.
  auto plain = OCIO::ViewTransform::Create(OCIO::REFERENCE_SPACE_SCENE);
  plain->setName(kUntonemapped);
  plain->setTransform(builtin(kAp0ToXyz), OCIO::VIEWTRANSFORM_DIR_FROM_REFERENCE);
  config.addViewTransform(plain);

  auto aces = OCIO::ViewTransform::Create(OCIO::REFERENCE_SPACE_SCENE);
  aces->setName(kAcesViewTransform);
  aces->setTransform(builtin(kAcesSdrVideo), OCIO::VIEWTRANSFORM_DIR_FROM_REFERENCE);
  config.addViewTransform(aces);
  config.setDefaultViewTransformName(kUntonemapped);
}

void add_displays(OCIO::Config& config) {
  for (auto [display, space] : {std::pair{kDisplaySRGB, kSRGBDisplaySpace},
                                std::pair{kDisplayRec1886, kRec1886DisplaySpace}}) {
    config.addDisplayView(display, kViewStandard, kUntonemapped, space, "", "", "");
    config.addDisplayView(display, kViewACES, kAcesViewTransform, space, "", "", "");
  }
}

}  // namespace

OCIO::ConstConfigRcPtr make_builtin_config() {
  auto config = OCIO::Config::Create();
  config->setName("brdfnav built-in");
  config->setDescription("brdfnav's config from OCIO 2.1 built-in transforms (docs/COLOR.md)");
  add_scene_spaces(*config);
  add_display_spaces(*config);
  add_view_transforms(*config);
  add_displays(*config);
  config->setRole(OCIO::ROLE_DEFAULT, kDefaultColorspace);
  config->setRole(OCIO::ROLE_SCENE_LINEAR, kDefaultColorspace);
  config->setRole(OCIO::ROLE_INTERCHANGE_SCENE, kAces2065);
  config->setRole(OCIO::ROLE_INTERCHANGE_DISPLAY, kXyzD65);
  config->validate();
  return config;
}

}  // namespace brdfnav::ocio
