// Several databases served at once, one per lighting (brdfnav/serve/lightings.h), called as the
// HTTP server calls it: two smoke databases the CLI builds here (forest.exr, the default map, and
// courtyard.exr), and the fuzzers' fixture database (interior.exr, without ggx).
#include <brdfnav/serve/lightings.h>

#include "cli_runner.h"

#include <unistd.h>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace brdfnav::serve {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const fs::path kWorld = "/usr/share/blender/datafiles/studiolights/world";

// The smoke profile (about a second) under `map` at `resolution` px, built once per process.
fs::path smoke_database(const std::string& name, const std::string& map, int resolution = 16) {
  // Removed when the process ends.
  struct Built : std::map<std::string, fs::path> {
    ~Built() {
      for (const auto& entry : *this) fs::remove_all(entry.second);
    }
  };
  static Built built;
  if (const auto it = built.find(name); it != built.end()) return it->second;
  const fs::path dir =
      fs::temp_directory_path() / ("brdfnav_lightings_" + std::to_string(::getpid()) + "_" + name);
  fs::remove_all(dir);
  const test::CliResult r =
      test::run_cli("precompute --profile smoke --res " + std::to_string(resolution) + " --env " +
                    (kWorld / map).string() + " --out " + dir.string());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return built[name] = dir;
}

fs::path fixture_database() {
  return fs::path(BRDFNAV_SOURCE_DIR) / "tests/fuzz/database";
}

// forest, courtyard and interior, in that order.
const LightingsApi& three() {
  static const LightingsApi api({ApiOptions{smoke_database("forest", "forest.exr"), 8},
                                 ApiOptions{smoke_database("courtyard", "courtyard.exr"), 8},
                                 ApiOptions{fixture_database(), 8}});
  return api;
}

struct Answer {
  int status;
  json body;
  std::string raw;
};

Answer call(std::string_view method, std::string_view path, const std::string& body = "",
            const std::multimap<std::string, std::string>& query = {}) {
  const ApiResponse r = three().handle({method, path, query, body});
  Answer a{r.status, json(), r.body};
  if (r.content_type == "application/json") a.body = json::parse(r.body);
  return a;
}

const std::string kWard =
    R"({"model": "ward", "params": {"alpha_x": 0.1, "alpha_y": 0.05}, "rho_d": [0.2, 0.2, 0.2],)"
    R"( "rho_s": [0.04, 0.04, 0.04], "colorspace": "lin_rec709"})";
const std::string kGgx =
    R"({"model": "ggx", "params": {"alpha_x": 0.1, "alpha_y": 0.1}, "rho_d": [0.2, 0.2, 0.2],)"
    R"( "rho_s": [0.04, 0.04, 0.04], "colorspace": "lin_rec709"})";

TEST(Lightings, ListsEveryDatabaseByItsMap) {
  const Answer a = call("GET", "/api/lightings");
  ASSERT_EQ(a.status, 200) << a.raw;
  EXPECT_EQ(a.body["default"], "forest");
  const json& list = a.body["lightings"];
  ASSERT_EQ(list.size(), 3u);
  EXPECT_EQ(list[0]["id"], "forest");
  EXPECT_EQ(list[1]["id"], "courtyard");
  EXPECT_EQ(list[2]["id"], "interior");
  EXPECT_EQ(list[1]["map"], "courtyard.exr");
  EXPECT_EQ(list[1]["path"], (kWorld / "courtyard.exr").string());
  EXPECT_EQ(list[0]["profile"], "smoke");
  EXPECT_EQ(list[2]["resolution"], 8);
  const std::vector<std::string> fixture_models = list[2]["models"];
  EXPECT_EQ(std::count(fixture_models.begin(), fixture_models.end(), "ggx"), 0);
  const std::vector<std::string> smoke_models = list[0]["models"];
  EXPECT_EQ(std::count(smoke_models.begin(), smoke_models.end(), "ggx"), 1);
}

TEST(Lightings, EachRequestGoesToItsLighting) {
  for (const auto& [id, map] : std::vector<std::pair<std::string, std::string>>{
           {"", "forest.exr"}, {"forest", "forest.exr"}, {"courtyard", "courtyard.exr"}}) {
    const std::multimap<std::string, std::string> query =
        id.empty() ? std::multimap<std::string, std::string>{}
                   : std::multimap<std::string, std::string>{{"lighting", id}};
    const Answer info = call("GET", "/api/info", "", query);
    ASSERT_EQ(info.status, 200) << info.raw;
    EXPECT_EQ(info.body["database"]["environment"]["path"], (kWorld / map).string()) << id;
  }
  const Answer unknown = call("GET", "/api/info", "", {{"lighting", "sunset"}});
  EXPECT_EQ(unknown.status, 400);
  EXPECT_EQ(unknown.body["error"],
            "lighting: no lighting \"sunset\" (expected one of: forest, courtyard, interior)");
  // A model the lighting's database lacks is refused by that database.
  const Answer ggx = call("POST", "/api/neighbors",
                          R"({"material": )" + kGgx + R"(, "radius": 0.03, "tab": "lobe"})",
                          {{"lighting", "interior"}});
  EXPECT_EQ(ggx.status, 400);
  EXPECT_NE(ggx.raw.find("holds no model 'ggx'"), std::string::npos) << ggx.raw;
}

// The PNG's width, height and mean 8-bit value.
struct Picture {
  int width = 0, height = 0;
  double mean = 0;
};

Picture decode(const std::string& png) {
  OIIO::Filesystem::IOMemReader memory(png.data(), png.size());
  const std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open("map.png", nullptr, &memory);
  EXPECT_TRUE(in) << OIIO::geterror();
  if (!in) return {};
  const OIIO::ImageSpec& spec = in->spec();
  std::vector<unsigned char> pixels(std::size_t(spec.width) * spec.height * spec.nchannels);
  EXPECT_TRUE(in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::UINT8, pixels.data()));
  double sum = 0;
  for (unsigned char p : pixels) sum += p;
  return {spec.width, spec.height, sum / double(pixels.size())};
}

TEST(Lightings, ShowsEachMapAsAPicture) {
  const ApiResponse forest = three().handle({"GET", "/api/environment", {}, ""});
  const ApiResponse courtyard =
      three().handle({"GET", "/api/environment", {{"lighting", "courtyard"}}, ""});
  ASSERT_EQ(forest.status, 200) << forest.body;
  EXPECT_EQ(forest.content_type, "image/png");
  const Picture a = decode(forest.body), b = decode(courtyard.body);
  EXPECT_EQ(a.width, kEnvironmentPicture);
  EXPECT_EQ(a.height, kEnvironmentPicture / 2);
  // Exposed to a mean of mid grey: neither black nor white, and two maps differ.
  for (const Picture& p : {a, b}) {
    EXPECT_EQ(p.width, kEnvironmentPicture);
    EXPECT_GT(p.mean, 20);
    EXPECT_LT(p.mean, 235);
  }
  EXPECT_NE(forest.body, courtyard.body);
  const ApiResponse bad =
      three().handle({"GET", "/api/environment", {{"display", "no such display"}}, ""});
  EXPECT_EQ(bad.status, 400);
  EXPECT_NE(bad.body.find("display"), std::string::npos) << bad.body;
}

TEST(Lightings, TheMaterialCarriesOverAsItIsWhereItsModelIsInBoth) {
  const Answer a = call("POST", "/api/carry", R"({"from": "forest", "material": )" + kWard + "}",
                        {{"lighting", "interior"}});
  ASSERT_EQ(a.status, 200) << a.raw;
  EXPECT_EQ(a.body["carried"], "same");
  EXPECT_EQ(a.body["material"], json::parse(kWard));
}

TEST(Lightings, AModelTheOtherLacksCarriesOverAsItsNearestMaterial) {
  const Answer a = call("POST", "/api/carry", R"({"from": "forest", "material": )" + kGgx + "}",
                        {{"lighting", "interior"}});
  ASSERT_EQ(a.status, 200) << a.raw;
  EXPECT_EQ(a.body["carried"], "nearest");
  EXPECT_NE(a.body["material"]["model"], "ggx");
  EXPECT_GE(a.body["residual"].get<double>(), 0);
  // The nearest of the forest database's fits of it among interior's models.
  const Answer info = call("GET", "/api/info", "", {{"lighting", "interior"}});
  bool held = false;
  for (const json& m : info.body["models"]) held = held || m["name"] == a.body["material"]["model"];
  EXPECT_TRUE(held) << a.raw;
}

TEST(Lightings, ACarryNamesWhatIsWrong) {
  const auto error = [](const std::string& body, const std::string& to) {
    const Answer a = call("POST", "/api/carry", body, {{"lighting", to}});
    EXPECT_EQ(a.status, 400) << a.raw;
    return a.body.value("error", "");
  };
  EXPECT_EQ(error(R"({"material": )" + kWard + "}", "forest"), "from: missing");
  EXPECT_EQ(error(R"({"from": "attic", "material": )" + kWard + "}", "forest"),
            "from: no lighting \"attic\" (expected one of: forest, courtyard, interior)");
  EXPECT_EQ(error(R"({"from": "forest", "material": )" + kWard + "}", "attic"),
            "lighting: no lighting \"attic\" (expected one of: forest, courtyard, interior)");
  EXPECT_EQ(error(R"({"from": "interior", "material": )" + kGgx + "}", "forest")
                .rfind("material.model: the database holds no model 'ggx'", 0),
            0u);
  EXPECT_EQ(call("GET", "/api/carry").status, 405);
  EXPECT_EQ(call("POST", "/api/lightings").status, 405);
}

TEST(Lightings, NamesTwoLightingsOfOneMapApart) {
  const LightingsApi api({ApiOptions{smoke_database("forest", "forest.exr"), 8},
                          ApiOptions{smoke_database("forest12", "forest.exr", 12), 8}});
  EXPECT_EQ(api.id(0), "forest");
  EXPECT_EQ(api.id(1), "forest-2");
}

TEST(Lightings, RefusesTwoDatabasesOfTheSameLightingNamingBoth) {
  const fs::path a = smoke_database("forest", "forest.exr");
  const fs::path b = fs::temp_directory_path() /
                     ("brdfnav_lightings_" + std::to_string(::getpid()) + "_forest_copy");
  fs::remove_all(b);
  fs::copy(a, b, fs::copy_options::recursive);
  struct Removed {
    fs::path dir;
    ~Removed() { fs::remove_all(dir); }
  } removed{b};
  try {
    LightingsApi api({ApiOptions{a, 8}, ApiOptions{b, 8}});
    ADD_FAILURE() << "served one lighting twice";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::invalid_argument);
    const std::string what = e.what();
    EXPECT_EQ(what.rfind(b.string() + ": the same map, profile and resolution as " + a.string(), 0),
              0u)
        << what;
  }
}

TEST(Lightings, ADatabaseThatDoesNotOpenIsNamed) {
  const fs::path missing = fs::temp_directory_path() / "brdfnav_lightings_none";
  try {
    LightingsApi api({ApiOptions{fixture_database(), 8}, ApiOptions{missing, 8}});
    ADD_FAILURE() << "opened a missing database";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()).rfind(missing.string() + ": ", 0), 0u) << e.what();
  }
}

}  // namespace
}  // namespace brdfnav::serve
