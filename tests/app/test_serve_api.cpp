// `brdfnav serve`'s JSON API (app/serve_api.h) called directly, as the HTTP server calls it, on
// the small fixture database of the fuzzers (tests/fuzz/database): the answers to requests the
// browser test cannot make as easily, such as very long names and every wrong method.
#include "serve_api.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <map>
#include <string>

namespace brdfnav::cli {
namespace {

const NavigatorApi& api() {
  static const NavigatorApi instance(
      ApiOptions{std::filesystem::path(BRDFNAV_SOURCE_DIR) / "tests/fuzz/database", 8});
  return instance;
}

const std::multimap<std::string, std::string> kNoQuery;

ApiResponse call(std::string_view method, std::string_view path, std::string_view body = "",
                 const std::multimap<std::string, std::string>& query = kNoQuery) {
  return api().handle({method, path, query, body});
}

std::string error_of(const ApiResponse& answer) {
  EXPECT_EQ(answer.content_type, "application/json");
  return nlohmann::json::parse(answer.body).at("error").get<std::string>();
}

const std::string kMaterial =
    R"({"model": "ward", "params": {"alpha_x": 0.1, "alpha_y": 0.05}, "rho_d": [0.2, 0.2, 0.2],)"
    R"( "rho_s": [0.04, 0.04, 0.04], "colorspace": "lin_rec709"})";

TEST(ServeApi, AnUnknownFieldsNameIsCutInTheMessage) {
  const std::string name(60000, 'x');
  const ApiResponse answer = call(
      "POST", "/api/neighbors",
      R"({"material": )" + kMaterial + R"(, "radius": 0.02, "tab": "lobe", ")" + name + R"(": 1})");
  EXPECT_EQ(answer.status, 400);
  EXPECT_LT(answer.body.size(), 300u);
  EXPECT_EQ(error_of(answer).rfind(std::string(77, 'x') + "...: unknown field (expected", 0), 0u)
      << answer.body;
  // A short name is quoted whole.
  EXPECT_EQ(error_of(call("POST", "/api/export", R"({"material": {}, "extra": 1})"))
                .rfind("extra: unknown field", 0),
            0u);
}

TEST(ServeApi, TheImportedFilesNameIsCutInTheMessage) {
  const std::multimap<std::string, std::string> query{{"name", std::string(60000, 'y') + ".yaml"}};
  const ApiResponse answer = call("POST", "/api/import", "model: [", query);
  EXPECT_EQ(answer.status, 400);
  EXPECT_LT(answer.body.size(), 300u);
  EXPECT_EQ(error_of(answer).rfind(std::string(77, 'y') + "...:", 0), 0u) << answer.body;
}

TEST(ServeApi, AWrongMethodIs405WithTheAllowedOnes) {
  struct Case {
    std::string method, path, allow;
  };
  for (const Case& c :
       {Case{"GET", "/api/neighbors", "POST"}, Case{"HEAD", "/api/export", "POST"},
        Case{"PUT", "/api/thumbnail", "POST"}, Case{"GET", "/api/import", "POST"},
        Case{"POST", "/api/info", "GET, HEAD"}, Case{"DELETE", "/api/info", "GET, HEAD"}}) {
    const ApiResponse answer = call(c.method, c.path, "{}");
    EXPECT_EQ(answer.status, 405) << c.method << " " << c.path;
    ASSERT_EQ(answer.headers.size(), 1u);
    EXPECT_EQ(answer.headers[0].first, "Allow");
    EXPECT_EQ(answer.headers[0].second, c.allow);
    EXPECT_EQ(error_of(answer),
              c.method + " " + c.path + ": method not allowed (allowed: " + c.allow + ")");
  }
}

TEST(ServeApi, AnUnknownPathIs404AndTheRightMethods200) {
  const ApiResponse missing = call("GET", "/api/nope");
  EXPECT_EQ(missing.status, 404);
  EXPECT_TRUE(missing.headers.empty());
  EXPECT_EQ(error_of(missing), "GET /api/nope: not found");
  EXPECT_EQ(call("GET", "/api/info").status, 200);
  EXPECT_EQ(call("HEAD", "/api/info").status, 200);
  EXPECT_EQ(call("POST", "/api/export", R"({"material": )" + kMaterial + "}").status, 200);
}

// A thumbnail is the exact render of its material unless a preview (the blend of the database's
// images) is asked for: between grid nodes the two differ, and the exact one comes back the same
// from the cache; a preview that is not a boolean is refused naming it.
TEST(ServeApi, ThumbnailsAreExactUnlessAPreviewIsAskedFor) {
  const std::string between =
      R"({"material": {"model": "ward", "params": {"alpha_x": 0.0731, "alpha_y": 0.0417},)"
      R"( "rho_d": [0.2, 0.2, 0.2], "rho_s": [0.5, 0.5, 0.5], "colorspace": "lin_rec709"})";
  const ApiResponse exact = call("POST", "/api/thumbnail", between + "}");
  ASSERT_EQ(exact.status, 200) << exact.body;
  EXPECT_EQ(exact.content_type, "image/png");
  const ApiResponse preview = call("POST", "/api/thumbnail", between + R"(, "preview": true})");
  ASSERT_EQ(preview.status, 200) << preview.body;
  EXPECT_NE(exact.body, preview.body);
  EXPECT_EQ(call("POST", "/api/thumbnail", between + R"(, "preview": false})").body, exact.body);
  const ApiResponse bad = call("POST", "/api/thumbnail", between + R"(, "preview": "yes"})");
  EXPECT_EQ(bad.status, 400);
  EXPECT_EQ(error_of(bad).rfind("preview: expected true or false", 0), 0u) << error_of(bad);
}

// Exact steps: each offer of the lobe tab moved until its render is at the radius from the
// material's (at the database's resolution, not the thumbnails'): unflagged ones within 2%,
// their distances the rendered ones, not the embedding's; an `exact` that is not a boolean is
// refused naming it.
TEST(ServeApi, ExactStepsAreAtTheRadiusByRendering) {
  const std::string query =
      R"({"material": )" + kMaterial + R"(, "radius": 0.02, "tab": "lobe", "exact": )";
  const ApiResponse plain = call("POST", "/api/neighbors", query + "false}");
  const ApiResponse exact = call("POST", "/api/neighbors", query + "true}");
  ASSERT_EQ(exact.status, 200) << exact.body;
  const auto offers = nlohmann::json::parse(exact.body).at("neighbors");
  const auto embedded = nlohmann::json::parse(plain.body).at("neighbors");
  ASSERT_EQ(offers.size(), embedded.size());
  int moved = 0;
  for (std::size_t i = 0; i < offers.size(); ++i) {
    if (!offers[i].at("flags").empty()) continue;
    EXPECT_NEAR(offers[i].at("distance").get<double>() / 0.02, 1, 0.02) << offers[i];
    moved += offers[i].at("material") != embedded[i].at("material");
  }
  EXPECT_GT(moved, 0);
  const ApiResponse bad = call("POST", "/api/neighbors", query + "1}");
  EXPECT_EQ(bad.status, 400);
  EXPECT_EQ(error_of(bad).rfind("exact: expected true or false", 0), 0u) << error_of(bad);
}

// The format of an export: yaml by default; a renderer's format needs a database with the ggx
// model, which the fixture (built before it existed) lacks: the answer says so.
TEST(ServeApi, TheExportsFormatIsCheckedAndARenderersNeedsGgx) {
  const ApiResponse yaml =
      call("POST", "/api/export", R"({"format": "yaml", "material": )" + kMaterial + "}");
  EXPECT_EQ(yaml.status, 200);
  EXPECT_EQ(yaml.content_type, "application/yaml");
  EXPECT_EQ(yaml.body, call("POST", "/api/export", R"({"material": )" + kMaterial + "}").body);
  const ApiResponse usd =
      call("POST", "/api/export", R"({"format": "usd", "material": )" + kMaterial + "}");
  EXPECT_EQ(usd.status, 400);
  EXPECT_EQ(error_of(usd), R"(format: expected one of yaml, materialx, cycles, got "usd")");
  for (const char* format : {"materialx", "cycles"}) {
    const ApiResponse answer =
        call("POST", "/api/export",
             std::string(R"({"format": ")") + format + R"(", "material": )" + kMaterial + "}");
    EXPECT_EQ(answer.status, 400) << format;
    EXPECT_NE(error_of(answer).find("holds no ggx model"), std::string::npos) << answer.body;
  }
}

}  // namespace
}  // namespace brdfnav::cli
