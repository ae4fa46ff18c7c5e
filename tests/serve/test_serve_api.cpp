// `brdfnav serve`'s JSON API (brdfnav/serve/serve_api.h) called directly, as the HTTP server calls
// it, on the small fixture database of the fuzzers (tests/fuzz/database): the answers to requests
// the browser test cannot make as easily, such as very long names and every wrong method.
#include <brdfnav/serve/serve_api.h>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <chrono>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <thread>
#include <vector>

namespace brdfnav::serve {
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

// The alpha channel of a PNG, and its size.
struct Alpha {
  int width = 0, height = 0;
  std::vector<unsigned char> values;
};
Alpha png_alpha(const std::string& png) {
  OIIO::Filesystem::IOMemReader memory(png.data(), png.size());
  const std::unique_ptr<OIIO::ImageInput> in =
      OIIO::ImageInput::open("thumbnail.png", nullptr, &memory);
  EXPECT_TRUE(in) << OIIO::geterror();
  if (!in) return {};
  const OIIO::ImageSpec& spec = in->spec();
  EXPECT_EQ(spec.nchannels, 4);
  std::vector<unsigned char> rgba(std::size_t(spec.width) * spec.height * 4);
  EXPECT_TRUE(in->read_image(0, 0, 0, 4, OIIO::TypeDesc::UINT8, rgba.data())) << in->geterror();
  Alpha a{spec.width, spec.height, {}};
  for (std::size_t i = 3; i < rgba.size(); i += 4) a.values.push_back(rgba[i]);
  return a;
}

// An exact thumbnail comes in the sizes /api/info lists (the thumbnails' resolution, then 256
// and 512), its alpha the sphere's coverage: partial along the edge, 0 in the corners, the disk's
// area in all; a preview only at the thumbnails' resolution; any other size is refused naming
// the sizes.
TEST(ServeApi, ThumbnailsComeInTheListedSizesWithAntialiasedEdges) {
  const auto info = nlohmann::json::parse(call("GET", "/api/info").body);
  EXPECT_EQ(info.at("thumbnail_sizes"), nlohmann::json::parse("[8, 256, 512]"));
  const std::string material = R"({"material": )" + kMaterial;
  const ApiResponse large = call("POST", "/api/thumbnail", material + R"(, "size": 256})");
  ASSERT_EQ(large.status, 200) << large.body;
  const Alpha a = png_alpha(large.body);
  ASSERT_EQ(a.width, 256);
  ASSERT_EQ(a.height, 256);
  double area = 0;
  int partial = 0;
  for (unsigned char v : a.values) area += v / 255.0, partial += v > 0 && v < 255;
  EXPECT_NEAR(area, 3.14159265358979 * 128 * 128, 0.001 * 128 * 128 * 3.14159265358979);
  EXPECT_GT(partial, 500);  // about 4 x 256 / sqrt(2) pixels are crossed by the edge
  EXPECT_EQ(a.values.front(), 0);
  EXPECT_EQ(a.values.back(), 0);
  EXPECT_EQ(png_alpha(call("POST", "/api/thumbnail", material + "}").body).width, 8);
  const ApiResponse odd = call("POST", "/api/thumbnail", material + R"(, "size": 100})");
  EXPECT_EQ(odd.status, 400);
  EXPECT_EQ(error_of(odd), "size: expected one of 8, 256, 512, got 100");
  const ApiResponse preview =
      call("POST", "/api/thumbnail", material + R"(, "size": 256, "preview": true})");
  EXPECT_EQ(preview.status, 400);
  EXPECT_EQ(error_of(preview), "size: a preview is drawn at 8 px only");
}

// A page numbers its rings; once it asks for a later one, the renders an earlier ring still
// waits for are dropped (409), while what is cached, or asked for by another page, comes back;
// a malformed ring is refused naming it.
TEST(ServeApi, TheRendersOfARingThePageHasLeftAreDropped) {
  const auto thumbnail = [](double alpha, const std::string& ring) {
    return call("POST", "/api/thumbnail",
                R"({"material": {"model": "ward", "params": {"alpha_x": )" + std::to_string(alpha) +
                    R"(, "alpha_y": 0.05}, "rho_d": [0.2, 0.2, 0.2], "rho_s": [0.04, 0.04, 0.04],)"
                    R"( "colorspace": "lin_rec709"}, "ring": )" +
                    ring + "}");
  };
  ASSERT_EQ(thumbnail(0.11, R"({"client": "page-a", "id": 1})").status, 200);
  ASSERT_EQ(thumbnail(0.12, R"({"client": "page-a", "id": 2})").status, 200);
  // Ring 1 is left: a render it would start is dropped, a cached image still answered.
  const ApiResponse left = thumbnail(0.13, R"({"client": "page-a", "id": 1})");
  EXPECT_EQ(left.status, 409);
  EXPECT_EQ(error_of(left), "ring: 1 of this page was left for a later one");
  EXPECT_EQ(thumbnail(0.11, R"({"client": "page-a", "id": 1})").status, 200);
  // Another page, and the current ring, render.
  EXPECT_EQ(thumbnail(0.13, R"({"client": "page-b", "id": 1})").status, 200);
  EXPECT_EQ(thumbnail(0.14, R"({"client": "page-a", "id": 2})").status, 200);
  // Exact steps of a left ring stop before their first render.
  const ApiResponse steps = call(
      "POST", "/api/neighbors",
      R"({"material": {"model": "ward", "params": {"alpha_x": 0.21, "alpha_y": 0.05},)"
      R"( "rho_d": [0.2, 0.2, 0.2], "rho_s": [0.04, 0.04, 0.04], "colorspace": "lin_rec709"},)"
      R"( "radius": 0.02, "tab": "lobe", "exact": true, "ring": {"client": "page-a", "id": 1}})");
  EXPECT_EQ(steps.status, 409) << steps.body;
  for (const char* bad : {R"("x")", R"({"client": "page-a"})", R"({"client": "", "id": 1})",
                          R"({"client": "a b", "id": 1})", R"({"client": "a", "id": -1})",
                          R"({"client": "a", "id": 1, "more": 2})"}) {
    const ApiResponse refused = thumbnail(0.1, bad);
    EXPECT_EQ(refused.status, 400) << bad;
    EXPECT_EQ(error_of(refused).rfind("ring: expected {", 0), 0u) << error_of(refused);
  }
}

// A ring the page leaves while its thumbnail renders: the render stops and the request answers
// 409. The page moves on once the render has had time to start (a 512 px render takes seconds
// here); had it not started, it would be dropped before starting, with the same answer.
// tests/lookdev/test_exact_thumbnails.cpp shows deterministically where the render stops.
TEST(ServeApi, ARingLeftWhileItsThumbnailRendersAnswers409) {
  ApiResponse running;
  std::thread page([&] {
    running = call("POST", "/api/thumbnail",
                   R"({"material": {"model": "ward", "params": {"alpha_x": 0.31, "alpha_y": 0.07},)"
                   R"( "rho_d": [0.2, 0.2, 0.2], "rho_s": [0.04, 0.04, 0.04],)"
                   R"( "colorspace": "lin_rec709"}, "size": 512,)"
                   R"( "ring": {"client": "page-r", "id": 1}})");
  });
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  const ApiResponse next = call("POST", "/api/thumbnail",
                                R"({"material": )" + kMaterial +
                                    R"(, "preview": true, "ring": {"client": "page-r", "id": 2}})");
  page.join();
  EXPECT_EQ(next.status, 200);
  EXPECT_EQ(running.status, 409) << running.body;
}

// The pages it remembers: the least recently heard from is forgotten first, and a late request
// of an older ring moves nothing back.
TEST(LeftRings, RemembersTheLatestRingOfTheMostRecentPages) {
  LeftRings rings(2);
  rings.enter({"a", 5});
  rings.enter({"a", 3});
  EXPECT_TRUE(rings.left({"a", 4}));
  EXPECT_FALSE(rings.left({"a", 5}));
  EXPECT_THROW(rings.check({"a", 4})(), RingLeft);
  EXPECT_NO_THROW(rings.check({"a", 5})());
  rings.enter({"b", 1});
  rings.enter({"a", 6});  // a heard from again: b is the least recent
  rings.enter({"c", 1});
  EXPECT_FALSE(rings.left({"b", 0}));  // forgotten
  EXPECT_TRUE(rings.left({"a", 5}));
  EXPECT_TRUE(rings.left({"c", 0}));
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
}  // namespace brdfnav::serve
