#include <brdfnav/ocio/color_pipeline.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "scratch_dir.h"

#include <OpenColorIO/OpenColorIO.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <latch>
#include <optional>
#include <sstream>
#include <thread>

namespace brdfnav::ocio {
namespace {

using test::ScratchDir;
using ::testing::HasSubstr;

// Sets (or unsets) $OCIO for one test and puts the old value back.
class OcioEnv {
 public:
  explicit OcioEnv(const std::optional<std::string>& value) {
    if (const char* old = std::getenv("OCIO")) old_ = old;
    if (value)
      ::setenv("OCIO", value->c_str(), 1);
    else
      ::unsetenv("OCIO");
  }
  ~OcioEnv() {
    if (old_)
      ::setenv("OCIO", old_->c_str(), 1);
    else
      ::unsetenv("OCIO");
  }

 private:
  std::optional<std::string> old_;
};

// Collects warnings instead of printing them.
struct Warnings {
  std::vector<std::string> seen;
  WarningSink sink() {
    return [this](const std::string& m) { seen.push_back(m); };
  }
};

ColorPipeline builtin_pipeline(Warnings& warnings) {
  PipelineOptions options;
  options.warn = warnings.sink();
  return ColorPipeline(options);
}

// IEC 61966-2-1 sRGB encoding of a linear value, clipped to [0, 1].
double srgb_encode(double x) {
  x = std::clamp(x, 0.0, 1.0);
  return x <= 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1.0 / 2.4) - 0.055;
}

std::vector<float> opaque_pixels(const std::vector<float>& rgb) {
  std::vector<float> rgba;
  for (std::size_t i = 0; i < rgb.size(); i += 3)
    rgba.insert(rgba.end(), {rgb[i], rgb[i + 1], rgb[i + 2], 1.0f});
  return rgba;
}

std::vector<float> apply_one(const ColorPipeline& p, std::vector<float> rgba, const char* view,
                             const char* display = kDisplaySRGB) {
  return p.apply_float(rgba.data(), static_cast<int>(rgba.size() / 4), 1, display, view);
}

TEST(BuiltinConfig, HasTheSRGBDisplayWithBothViews) {
  OcioEnv env(std::nullopt);
  Warnings warnings;
  const ColorPipeline p = builtin_pipeline(warnings);
  EXPECT_EQ(p.config_source(), kBuiltinConfigName);
  EXPECT_EQ(p.source_colorspace(), "lin_rec709");
  EXPECT_EQ(p.describe(), "OCIO config: built-in; source colour space: lin_rec709");
  EXPECT_EQ(p.displays(), (std::vector<std::string>{"sRGB", "Rec.1886"}));
  EXPECT_EQ(p.views("sRGB"), (std::vector<std::string>{"Standard", "ACES 1.0 SDR-video"}));
  EXPECT_EQ(p.default_display(), "sRGB");
  EXPECT_EQ(p.default_view("sRGB"), "Standard");
  EXPECT_TRUE(warnings.seen.empty()) << warnings.seen.front();
}

TEST(BuiltinConfig, SourceAcceptsRolesAndAliases) {
  OcioEnv env(std::nullopt);
  for (const char* name : {"scene_linear", "Linear Rec.709 (sRGB)", "lin_srgb"}) {
    PipelineOptions options;
    options.source = name;
    EXPECT_EQ(ColorPipeline(options).source_colorspace(), "lin_rec709") << name;
  }
  PipelineOptions aces;
  aces.source = "lin_ap1";
  EXPECT_EQ(ColorPipeline(aces).source_colorspace(), "ACEScg");
}

TEST(BuiltinConfig, UnknownSourceFallsBackToSceneLinearWithAWarning) {
  OcioEnv env(std::nullopt);
  Warnings warnings;
  PipelineOptions options;
  options.source = "no_such_space";
  options.warn = warnings.sink();
  EXPECT_EQ(ColorPipeline(options).source_colorspace(), "lin_rec709");
  ASSERT_EQ(warnings.seen.size(), 1u);
  EXPECT_THAT(warnings.seen[0], HasSubstr("'no_such_space'"));
  EXPECT_THAT(warnings.seen[0], HasSubstr("scene_linear"));
}

// Linear Rec.709 reaches the sRGB display through four float matrices (Rec.709 -> AP1 -> AP0 ->
// XYZ -> Rec.709) whose product is the identity to ~1e-6; the curve's steepest slope (12.92)
// makes that ~1e-5, measured 8e-6. Hence 1e-4 on floats, and 1 code value (1/255) on bytes: an
// exact value within 1e-4 of a rounding boundary may round either way.
TEST(BuiltinConfig, StandardViewIsThePiecewiseSRGBCurve) {
  OcioEnv env(std::nullopt);
  Warnings warnings;
  const ColorPipeline p = builtin_pipeline(warnings);
  const std::vector<float> rgb = {0.0f,  0.001f, 0.0031308f, 0.01f, 0.18f, 0.5f, 1.0f, 2.0f,
                                  -0.1f, 0.8f,   0.2f,       0.05f, 0.0f,  1.0f, 0.3f};
  auto rgba = opaque_pixels(rgb);
  const int n = static_cast<int>(rgba.size() / 4);
  const auto f = p.apply_float(rgba.data(), n, 1, kDisplaySRGB, kViewStandard);
  const auto b = p.apply(rgba.data(), n, 1, kDisplaySRGB, kViewStandard);
  for (int i = 0; i < n; ++i) {
    for (int c = 0; c < 3; ++c) {
      const double want = srgb_encode(rgb[3 * i + c]);
      EXPECT_NEAR(f[4 * i + c], want, 1e-4) << "pixel " << i << " channel " << c;
      EXPECT_NEAR(b[4 * i + c], want * 255.0, 1.0) << "pixel " << i << " channel " << c;
    }
    EXPECT_EQ(f[4 * i + 3], 1.0f);
    EXPECT_EQ(b[4 * i + 3], 255);
  }
}

// ACES 1.0 RRT + sRGB (100 nit, dim surround) ODT, from the CTL's design points: the RRT and
// the 48-nit ODT spline take scene 0.18 to 4.8 nits; the video ODT rescales [0.02, 48] nits to
// [0, 1] (0.0996), applies the dim-surround gamma 0.9811 (0.1041) and the sRGB curve: 0.356.
TEST(BuiltinConfig, AcesViewTonemapsToKnownValues) {
  OcioEnv env(std::nullopt);
  Warnings warnings;
  const ColorPipeline p = builtin_pipeline(warnings);
  const auto black = apply_one(p, {0, 0, 0, 1}, kViewACES);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(black[c], 0.0, 1e-4);
  const auto grey = apply_one(p, {0.18f, 0.18f, 0.18f, 1}, kViewACES);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(grey[c], 0.356, 0.005);

  // A ramp stays neutral and rises strictly from the toe on until the ODT clips it at 1, between
  // 16 and 25 linear (the Standard view clips at 1.0).
  float previous = -1.0f;
  for (float x = 0.005f; x < 50.0f; x *= 1.5f) {
    const auto out = apply_one(p, {x, x, x, 1}, kViewACES);
    EXPECT_TRUE(out[0] > previous || out[0] == 1.0f) << x << ": " << out[0];
    EXPECT_NEAR(out[1], out[0], 1e-4);
    EXPECT_NEAR(out[2], out[0], 1e-4);
    EXPECT_LE(out[0], 1.0f);
    previous = out[0];
  }
  EXPECT_LT(apply_one(p, {1, 1, 1, 1}, kViewACES)[0], 0.9f);  // the Standard view gives 1
}

TEST(BuiltinConfig, UncoveredPixelsShowTheBackgroundAndKeepTheirAlpha) {
  OcioEnv env(std::nullopt);
  Warnings warnings;
  const ColorPipeline p = builtin_pipeline(warnings);
  const auto out = apply_one(p, {0, 0, 0, 0, 0.18f, 0.18f, 0.18f, 1}, kViewStandard);
  for (int c = 0; c < 3; ++c) EXPECT_FLOAT_EQ(out[c], out[4 + c]);
  EXPECT_EQ(out[3], 0.0f);
  EXPECT_EQ(out[7], 1.0f);
}

TEST(BuiltinConfig, OtherDisplaysUseTheirOwnEncoding) {
  OcioEnv env(std::nullopt);
  Warnings warnings;
  const ColorPipeline p = builtin_pipeline(warnings);
  // Rec.1886 with a zero black level is a pure 2.4 power.
  const auto out = apply_one(p, {0.18f, 0.18f, 0.18f, 1}, kViewStandard, kDisplayRec1886);
  EXPECT_NEAR(out[0], std::pow(0.18, 1.0 / 2.4), 1e-4);
}

TEST(BuiltinConfig, UnknownDisplayOrViewListsTheValidOnes) {
  OcioEnv env(std::nullopt);
  Warnings warnings;
  const ColorPipeline p = builtin_pipeline(warnings);
  try {
    p.validate("Nope", kViewStandard);
    FAIL() << "no error";
  } catch (const ColorError& e) {
    EXPECT_THAT(e.what(), HasSubstr("'Nope'"));
    EXPECT_THAT(e.what(), HasSubstr("'sRGB', 'Rec.1886'"));
  }
  try {
    const float px[4] = {0, 0, 0, 1};
    p.apply(px, 1, 1, kDisplaySRGB, "Filmic");
    FAIL() << "no error";
  } catch (const ColorError& e) {
    EXPECT_THAT(e.what(), HasSubstr("'Filmic'"));
    EXPECT_THAT(e.what(), HasSubstr("'sRGB'"));
    EXPECT_THAT(e.what(), HasSubstr("'Standard', 'ACES 1.0 SDR-video'"));
  }
  EXPECT_THROW(p.views("Nope"), ColorError);
}

TEST(BuiltinConfig, RejectsMalformedBuffers) {
  OcioEnv env(std::nullopt);
  Warnings warnings;
  const ColorPipeline p = builtin_pipeline(warnings);
  EXPECT_THROW(p.apply(nullptr, 2, 2, kDisplaySRGB, kViewStandard), ColorError);
  const float px[4] = {0, 0, 0, 1};
  EXPECT_THROW(p.apply(px, -1, 1, kDisplaySRGB, kViewStandard), ColorError);
  EXPECT_TRUE(p.apply(nullptr, 0, 0, kDisplaySRGB, kViewStandard).empty());
}

TEST(ProcessorCache, BuildsEachProcessorOnce) {
  OcioEnv env(std::nullopt);
  Warnings warnings;
  const ColorPipeline p = builtin_pipeline(warnings);
  const auto aces = p.processor(kDisplaySRGB, kViewACES);
  EXPECT_EQ(p.processor(kDisplaySRGB, kViewACES), aces);
  EXPECT_NE(p.processor(kDisplaySRGB, kViewStandard), aces);
  EXPECT_NE(p.processor(kDisplayRec1886, kViewACES), aces);
}

TEST(ProcessorCache, ConcurrentAppliesGiveIdenticalBytes) {
  OcioEnv env(std::nullopt);
  Warnings warnings;
  const ColorPipeline p = builtin_pipeline(warnings);
  constexpr int kSize = 64, kThreads = 8;
  std::vector<float> image(4 * kSize * kSize);
  for (std::size_t i = 0; i < image.size(); ++i)
    image[i] = (i % 4 == 3) ? float(i % 7 != 0) : 0.0005f * float(i % 4001);
  std::vector<std::vector<std::uint8_t>> results(kThreads);
  std::latch start(kThreads);
  std::vector<std::thread> threads;
  // Nobody has asked for the ACES processor yet, so the threads also race to build it.
  for (int t = 0; t < kThreads; ++t)
    threads.emplace_back([&, t] {
      start.arrive_and_wait();
      results[t] = p.apply(image.data(), kSize, kSize, kDisplaySRGB, kViewACES);
    });
  for (auto& thread : threads) thread.join();
  const auto serial = p.apply(image.data(), kSize, kSize, kDisplaySRGB, kViewACES);
  for (int t = 0; t < kThreads; ++t) EXPECT_EQ(results[t], serial) << "thread " << t;
}

// A small v2 config: linear (alias lin_rec709) shown on one display through a 1/2 power.
constexpr const char* kSquareRootConfig = R"(ocio_profile_version: 2
roles:
  default: linear
  scene_linear: linear
file_rules:
  - !<Rule> {name: Default, colorspace: default}
displays:
  Test Display:
    - !<View> {name: Square root, colorspace: sqrt}
colorspaces:
  - !<ColorSpace>
    name: linear
    aliases: [lin_rec709]
  - !<ColorSpace>
    name: sqrt
    from_scene_reference: !<ExponentTransform> {value: [2, 2, 2, 1], direction: inverse}
)";

TEST(EnvConfig, IsUsedAndNamed) {
  ScratchDir dir;
  const auto file = dir.write("square_root.ocio", kSquareRootConfig);
  OcioEnv env(file.string());
  Warnings warnings;
  const ColorPipeline p = builtin_pipeline(warnings);
  EXPECT_EQ(p.config_source(), file.string());
  EXPECT_THAT(p.describe(), HasSubstr(file.string()));
  EXPECT_EQ(p.source_colorspace(), "linear");
  EXPECT_EQ(p.displays(), std::vector<std::string>{"Test Display"});
  const auto out = apply_one(p, {0.25f, 0.04f, 0.81f, 1}, "Square root", "Test Display");
  EXPECT_NEAR(out[0], 0.5, 1e-5);
  EXPECT_NEAR(out[1], 0.2, 1e-5);
  EXPECT_NEAR(out[2], 0.9, 1e-5);
  EXPECT_TRUE(warnings.seen.empty());
}

TEST(EnvConfig, MissingOrGarbageFileIsAnErrorNamingIt) {
  ScratchDir dir;
  const auto missing = dir.path() / "missing.ocio";
  const auto garbage = dir.write("garbage.ocio", "this: [is not, a config\n\t}}");
  for (const auto& file : {missing, garbage}) {
    OcioEnv env(file.string());
    try {
      ColorPipeline p;
      FAIL() << "no error for " << file;
    } catch (const ColorError& e) {
      EXPECT_THAT(e.what(), HasSubstr("'" + file.string() + "'"));
      EXPECT_THAT(e.what(), HasSubstr("$OCIO"));
    }
  }
}

TEST(EnvConfig, ExplicitPathWinsOverTheEnvironment) {
  ScratchDir dir;
  const auto file = dir.write("square_root.ocio", kSquareRootConfig);
  OcioEnv env((dir.path() / "missing.ocio").string());
  PipelineOptions options;
  options.config_path = file.string();
  EXPECT_EQ(ColorPipeline(options).config_source(), file.string());
}

TEST(EnvConfig, RawConfigWarnsOnce) {
  ScratchDir dir;
  std::ostringstream raw;
  OCIO_NAMESPACE::Config::CreateRaw()->serialize(raw);
  const auto file = dir.write("raw.ocio", raw.str());
  OcioEnv env(file.string());
  Warnings warnings;
  const ColorPipeline p = builtin_pipeline(warnings);
  const auto out = apply_one(p, {0.18f, 0.5f, 0.7f, 1}, "Raw");
  apply_one(p, {0.18f, 0.5f, 0.7f, 1}, "Raw");
  EXPECT_NEAR(out[0], 0.18, 1e-6);  // identity, which is why it must not pass silently
  // One warning for the missing lin_rec709 (the default role stands in), one for the identity.
  ASSERT_EQ(warnings.seen.size(), 2u);
  EXPECT_THAT(warnings.seen[0], HasSubstr("'lin_rec709'"));
  EXPECT_THAT(warnings.seen[1], HasSubstr("not colour-managed"));
  EXPECT_THAT(warnings.seen[1], HasSubstr(file.string()));
}

}  // namespace
}  // namespace brdfnav::ocio
