// brdfnav::Error: a code and a message naming what is at fault, kept through the layers' own
// types and through with_context().
#include <brdfnav/core/atomic_file.h>
#include <brdfnav/core/error.h>
#include <brdfnav/core/material.h>
#include <brdfnav/core/warning.h>

#include <gtest/gtest.h>

#include <string>

namespace brdfnav {
namespace {

TEST(Error, CarriesItsCodeAndContext) {
  const Error plain(ErrorCode::database, "db/manifest.yaml: missing");
  EXPECT_EQ(plain.code(), ErrorCode::database);
  EXPECT_STREQ(plain.what(), "db/manifest.yaml: missing");
  EXPECT_TRUE(plain.context().empty());

  const Error named(ErrorCode::invalid_argument, "radius", "must be positive");
  EXPECT_STREQ(named.what(), "radius: must be positive");
  EXPECT_EQ(named.context(), "radius");
}

TEST(Error, ALayersTypeHasItsDefaultCodeUnlessTheThrowerKnowsBetter) {
  try {
    parse_material_spec("ward:alpha_x=abc");
    FAIL() << "no error";
  } catch (const Error& e) {  // a MaterialError, caught as the one type
    EXPECT_EQ(e.code(), ErrorCode::parse);
    EXPECT_NE(dynamic_cast<const MaterialError*>(&e), nullptr);
  }
  Material acescg = default_material(ModelId::ward);
  acescg.colorspace = "acescg";
  try {
    require_render_colorspace(acescg);
    FAIL() << "no error";
  } catch (const MaterialError& e) {
    EXPECT_EQ(e.code(), ErrorCode::invalid_argument);  // the caller's material, not a file's
  }
}

TEST(Error, WithContextKeepsTheCode) {
  try {
    with_context("--material", [] { (void)read_file("/nonexistent/brdfnav/m.yaml"); });
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::io);
    EXPECT_EQ(e.context(), "--material");
    EXPECT_EQ(
        std::string(e.what()).rfind("--material: /nonexistent/brdfnav/m.yaml: cannot open", 0), 0u)
        << e.what();
  }
  EXPECT_EQ(with_context("--radius", [] { return 3; }), 3);
}

TEST(Warnings, DefaultSinkWritesToStderr) {
  ::testing::internal::CaptureStderr();
  warn_to_stderr("something odd");
  EXPECT_EQ(::testing::internal::GetCapturedStderr(), "brdfnav: warning: something odd\n");
}

}  // namespace
}  // namespace brdfnav
