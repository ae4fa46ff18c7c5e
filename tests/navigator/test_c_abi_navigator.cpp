// The navigator through the C ABI of a dlopen()ed libbrdfnav_navigator.so (plugin_api.h), against
// the C++ navigator linked into this test: the same neighbours and display thumbnails, the ABI's
// statuses and messages; its neighbours' materials make closures of libbrdfnav.so.
#include "navigator/navigator_fixture.h"
#include "plugin/plugin_api.h"

#include <brdfnav/navigator/display_thumbnails.h>
#include <brdfnav/navigator/navigator.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace brdfnav {
namespace {

using test::api;
using test::navigator_api;
using ::testing::HasSubstr;

struct NavigatorHandle {
  brdfnav_navigator* navigator = nullptr;
  ~NavigatorHandle() { navigator_api().navigator_close(navigator); }
};
struct ListHandle {
  brdfnav_neighbors* list = nullptr;
  ~ListHandle() { navigator_api().neighbors_free(list); }
};

class CAbiNavigator : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_NO_THROW(api());
    ASSERT_NO_THROW(navigator_api());
    ASSERT_EQ(c.navigator_open(db().c_str(), &nav.navigator), BRDFNAV_OK) << c.navigator_geterror();
  }
  static const std::filesystem::path& db() { return test::NavigationDatabase::get().dir(); }
  static const Navigator& reference() {
    static const Navigator n = Navigator::open(db());
    return n;
  }
  const test::NavigatorApi& c = navigator_api();
  NavigatorHandle nav;
};

// Every neighbour of a C list equals the C++ navigator's.
void expect_list(const brdfnav_neighbors* list, const std::vector<Neighbor>& expected) {
  const test::NavigatorApi& c = navigator_api();
  size_t count = 0;
  ASSERT_EQ(c.neighbors_count(list, &count), BRDFNAV_OK);
  ASSERT_EQ(count, expected.size());
  for (size_t i = 0; i < count; ++i) {
    brdfnav_neighbor n;
    ASSERT_EQ(c.neighbors_get(list, i, &n), BRDFNAV_OK);
    const Neighbor& e = expected[i];
    EXPECT_EQ(n.tab, static_cast<brdfnav_tab>(e.tab));
    EXPECT_EQ(n.label, e.label);
    EXPECT_EQ(n.distance, e.distance);
    EXPECT_EQ(n.flags, (e.at_boundary ? BRDFNAV_NEIGHBOR_AT_BOUNDARY : 0u) |
                           (e.clamped ? BRDFNAV_NEIGHBOR_CLAMPED : 0u) |
                           (e.beyond_radius ? BRDFNAV_NEIGHBOR_BEYOND_RADIUS : 0u));
    EXPECT_EQ(n.words, e.words);
    EXPECT_EQ(n.change, e.change);
    EXPECT_EQ(n.opposite, e.opposite);
    const ModelInfo& info = model_info(e.material.model);
    EXPECT_EQ(n.material.model, info.name);
    ASSERT_EQ(n.material.param_count, info.params.size());
    for (size_t p = 0; p < n.material.param_count; ++p) {
      EXPECT_EQ(n.material.params[p].name, info.params[p].name);
      EXPECT_EQ(n.material.params[p].value, e.material.params[p]);
    }
    for (int ch = 0; ch < 3; ++ch) {
      EXPECT_EQ(n.material.rho_d[ch], e.material.rho_d[ch]);
      EXPECT_EQ(n.material.rho_s[ch], e.material.rho_s[ch]);
    }
    EXPECT_EQ(n.material.colorspace, e.material.colorspace);
    // The neighbour is a material the ABI takes back.
    brdfnav_closure* closure = nullptr;
    EXPECT_EQ(api().closure_create(&n.material, &closure), BRDFNAV_OK) << api().geterror();
    api().closure_destroy(closure);
  }
}

TEST_F(CAbiNavigator, ListsTheCppNeighboursOfEveryTab) {
  const char* spec = "cook_torrance:f0=0.2,m=0.1,rho_d=0.1/0.2/0.3,rho_s=0.6";
  const brdfnav_param_value params[] = {{"m", 0.1}, {"f0", 0.2}};
  const brdfnav_material current{"cook_torrance", params,          2,
                                 {0.1, 0.2, 0.3}, {0.6, 0.6, 0.6}, nullptr};
  for (Tab tab : kTabs) {
    SCOPED_TRACE(std::string(tab_name(tab)));
    const auto expected = reference().neighbors(parse_material_spec(spec), 0.02, tab, 5);
    ListHandle from_struct, from_spec;
    ASSERT_EQ(c.navigator_neighbors(nav.navigator, &current, 0.02, static_cast<brdfnav_tab>(tab), 5,
                                    &from_struct.list),
              BRDFNAV_OK)
        << c.navigator_geterror();
    expect_list(from_struct.list, expected);
    ASSERT_EQ(c.navigator_neighbors_load(nav.navigator, spec, 0.02, static_cast<brdfnav_tab>(tab),
                                         5, &from_spec.list),
              BRDFNAV_OK)
        << c.navigator_geterror();
    expect_list(from_spec.list, expected);
  }
  ListHandle gallery;
  ASSERT_EQ(c.navigator_gallery(nav.navigator, 6, &gallery.list), BRDFNAV_OK)
      << c.navigator_geterror();
  expect_list(gallery.list, reference().gallery(6));
}

// A list outlives its navigator: it owns every string and array it hands out.
TEST_F(CAbiNavigator, ListsOutliveTheirNavigator) {
  ListHandle list;
  ASSERT_EQ(c.navigator_neighbors_load(nav.navigator, "ward:alpha_x=0.1,alpha_y=0.03,rho_s=0.5",
                                       0.01, BRDFNAV_TAB_LOBE, 8, &list.list),
            BRDFNAV_OK);
  c.navigator_close(nav.navigator);
  nav.navigator = nullptr;
  brdfnav_neighbor n;
  ASSERT_EQ(c.neighbors_get(list.list, 5, &n), BRDFNAV_OK);
  EXPECT_STREQ(n.label, "alpha-");
  EXPECT_STREQ(n.material.model, "ward");
  EXPECT_STREQ(n.material.colorspace, "lin_rec709");
}

TEST_F(CAbiNavigator, ReportsBadQueriesWithStatusAndMessage) {
  const auto expect_failure = [&](brdfnav_status status, brdfnav_status expected,
                                  const std::string& message) {
    EXPECT_EQ(status, expected) << message;
    EXPECT_THAT(c.navigator_geterror(), HasSubstr(message));
  };
  brdfnav_navigator* none = reinterpret_cast<brdfnav_navigator*>(&none);
  expect_failure(c.navigator_open("/nonexistent/db", &none), BRDFNAV_ERROR_DATABASE,
                 "/nonexistent/db/manifest.yaml");
  EXPECT_EQ(none, nullptr);
  expect_failure(c.navigator_open(nullptr, &none), BRDFNAV_ERROR_INVALID_ARGUMENT, "database_dir");

  const brdfnav_material ward{"ward", nullptr, 0, {0.2, 0.2, 0.2}, {0.3, 0.3, 0.3}, nullptr};
  brdfnav_neighbors* list = reinterpret_cast<brdfnav_neighbors*>(&list);
  for (double radius : {0.0, -1.0, double(NAN), double(INFINITY)})
    expect_failure(c.navigator_neighbors(nav.navigator, &ward, radius, BRDFNAV_TAB_LOBE, 8, &list),
                   BRDFNAV_ERROR_INVALID_ARGUMENT, "radius");
  EXPECT_EQ(list, nullptr);
  expect_failure(
      c.navigator_neighbors(nav.navigator, &ward, 0.01, static_cast<brdfnav_tab>(9), 8, &list),
      BRDFNAV_ERROR_INVALID_ARGUMENT, "tab 9");
  expect_failure(c.navigator_neighbors(nav.navigator, &ward, 0.01, BRDFNAV_TAB_MODELS, 0, &list),
                 BRDFNAV_ERROR_INVALID_ARGUMENT, "clusters");
  expect_failure(c.navigator_neighbors(nullptr, &ward, 0.01, BRDFNAV_TAB_LOBE, 8, &list),
                 BRDFNAV_ERROR_INVALID_ARGUMENT, "navigator");
  expect_failure(c.navigator_neighbors(nav.navigator, nullptr, 0.01, BRDFNAV_TAB_LOBE, 8, &list),
                 BRDFNAV_ERROR_INVALID_ARGUMENT, "current");
  expect_failure(c.navigator_neighbors(nav.navigator, &ward, 0.01, BRDFNAV_TAB_LOBE, 8, nullptr),
                 BRDFNAV_ERROR_INVALID_ARGUMENT, "out");
  const brdfnav_material acescg{"ward", nullptr, 0, {0.2, 0.2, 0.2}, {0.3, 0.3, 0.3}, "acescg"};
  expect_failure(c.navigator_neighbors(nav.navigator, &acescg, 0.01, BRDFNAV_TAB_DIFFUSE, 8, &list),
                 BRDFNAV_ERROR_INVALID_ARGUMENT, "colorspace 'acescg'");
  expect_failure(
      c.navigator_neighbors_load(nav.navigator, "ward:alpha_x=3", 0.01, BRDFNAV_TAB_LOBE, 8, &list),
      BRDFNAV_ERROR_PARSE, "params.alpha_x");
  expect_failure(c.navigator_neighbors_load(nav.navigator, "/nonexistent/m.yaml", 0.01,
                                            BRDFNAV_TAB_LOBE, 8, &list),
                 BRDFNAV_ERROR_IO, "/nonexistent/m.yaml");
  expect_failure(c.navigator_gallery(nav.navigator, 0, &list), BRDFNAV_ERROR_INVALID_ARGUMENT,
                 "clusters");
  EXPECT_EQ(list, nullptr);

  ListHandle ok;
  ASSERT_EQ(c.navigator_gallery(nav.navigator, 2, &ok.list), BRDFNAV_OK);
  size_t count = 7;
  brdfnav_neighbor n{};
  n.distance = -7;
  expect_failure(c.neighbors_get(ok.list, 2, &n), BRDFNAV_ERROR_INVALID_ARGUMENT,
                 "neighbour index 2");
  EXPECT_EQ(n.distance, -7);
  expect_failure(c.neighbors_get(nullptr, 0, &n), BRDFNAV_ERROR_INVALID_ARGUMENT, "list");
  expect_failure(c.neighbors_get(ok.list, 0, nullptr), BRDFNAV_ERROR_INVALID_ARGUMENT, "out");
  expect_failure(c.neighbors_count(nullptr, &count), BRDFNAV_ERROR_INVALID_ARGUMENT, "list");
  expect_failure(c.neighbors_count(ok.list, nullptr), BRDFNAV_ERROR_INVALID_ARGUMENT, "count");
  EXPECT_EQ(count, 7u);
  c.neighbors_free(nullptr);
  c.navigator_close(nullptr);
}

// The library reports the header's version, and the loader's check refuses it for a host built
// against another: version 2, whose thumbnails were composited over grey with a 0/1 alpha.
TEST(CAbiNavigatorVersion, IsTheHeadersAndALoaderOfAnotherRefusesIt) {
  static_assert(BRDFNAV_NAVIGATOR_ABI_VERSION == 3);
  EXPECT_NO_THROW(test::open_library(BRDFNAV_NAVIGATOR_PATH, "brdfnav_navigator_abi_version",
                                     BRDFNAV_NAVIGATOR_ABI_VERSION));
  try {
    test::open_library(BRDFNAV_NAVIGATOR_PATH, "brdfnav_navigator_abi_version", 2);
    ADD_FAILURE() << "a library of version 3 was accepted for version 2";
  } catch (const std::runtime_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("ABI version 3, expected 2"));
  }
}

// $OCIO unset for the life of a test, restored after: the display thumbnails' tests name the
// built-in config's sRGB display and Standard view.
class BuiltinOcioConfig {
 public:
  BuiltinOcioConfig() {
    if (const char* old = std::getenv("OCIO")) old_ = old;
    ::unsetenv("OCIO");
  }
  ~BuiltinOcioConfig() {
    if (old_) ::setenv("OCIO", old_->c_str(), 1);
  }

 private:
  std::optional<std::string> old_;
};

// The displays and views the ABI lists are the C++ pipeline's, in its order.
TEST_F(CAbiNavigator, ListsTheOcioDisplaysAndViews) {
  const BuiltinOcioConfig builtin;
  const ocio::ColorPipeline reference;
  size_t count = 0;
  ASSERT_EQ(c.navigator_displays(nav.navigator, &count), BRDFNAV_OK) << c.navigator_geterror();
  const std::vector<std::string> displays = reference.displays();
  ASSERT_EQ(count, displays.size());
  for (size_t i = 0; i < count; ++i) {
    const char* name = nullptr;
    ASSERT_EQ(c.navigator_display(nav.navigator, i, &name), BRDFNAV_OK) << c.navigator_geterror();
    EXPECT_EQ(name, displays[i]);
    const std::vector<std::string> views = reference.views(displays[i]);
    size_t view_count = 0;
    ASSERT_EQ(c.navigator_views(nav.navigator, name, &view_count), BRDFNAV_OK);
    ASSERT_EQ(view_count, views.size());
    for (size_t j = 0; j < view_count; ++j) {
      const char* view = nullptr;
      ASSERT_EQ(c.navigator_view(nav.navigator, name, j, &view), BRDFNAV_OK);
      EXPECT_EQ(view, views[j]);
    }
  }
  // The first of each list is the config's default.
  const char* first = nullptr;
  ASSERT_EQ(c.navigator_display(nav.navigator, 0, &first), BRDFNAV_OK);
  EXPECT_EQ(first, reference.default_display());
  ASSERT_EQ(c.navigator_view(nav.navigator, first, 0, &first), BRDFNAV_OK);
  EXPECT_EQ(first, reference.default_view(reference.default_display()));

  const char* untouched = "untouched";
  EXPECT_EQ(c.navigator_display(nav.navigator, count, &untouched), BRDFNAV_ERROR_INVALID_ARGUMENT);
  EXPECT_THAT(c.navigator_geterror(), HasSubstr("display index " + std::to_string(count)));
  EXPECT_EQ(c.navigator_views(nav.navigator, "Nonesuch", &count), BRDFNAV_ERROR_INVALID_ARGUMENT);
  EXPECT_THAT(c.navigator_geterror(), HasSubstr("display 'Nonesuch'"));
  EXPECT_THAT(c.navigator_geterror(), HasSubstr("'sRGB'"));
  EXPECT_EQ(c.navigator_view(nav.navigator, "sRGB", 99, &untouched),
            BRDFNAV_ERROR_INVALID_ARGUMENT);
  EXPECT_THAT(c.navigator_geterror(), HasSubstr("view index 99"));
  EXPECT_STREQ(untouched, "untouched");
  EXPECT_EQ(c.navigator_displays(nullptr, &count), BRDFNAV_ERROR_INVALID_ARGUMENT);
  EXPECT_THAT(c.navigator_geterror(), HasSubstr("navigator"));
  EXPECT_EQ(c.navigator_views(nav.navigator, nullptr, &count), BRDFNAV_ERROR_INVALID_ARGUMENT);
  EXPECT_THAT(c.navigator_geterror(), HasSubstr("display"));
}

// The first gallery material of the database, as the C ABI hands it out, and as C++ sees it.
struct GalleryMaterial {
  explicit GalleryMaterial(const brdfnav_navigator* navigator) {
    EXPECT_EQ(navigator_api().navigator_gallery(navigator, 3, &list.list), BRDFNAV_OK);
    brdfnav_neighbor n;
    EXPECT_EQ(navigator_api().neighbors_get(list.list, 0, &n), BRDFNAV_OK);
    c = n.material;
  }
  ListHandle list;
  brdfnav_material c{};
};

// A database material's thumbnail in sRGB / Standard is the C++ display thumbnail byte for byte,
// which is display_encode() of the linear thumbnail at the database's resolution (what the server
// shows): straight alpha, the sphere's edge antialiased.
TEST_F(CAbiNavigator, ThumbnailsMatchTheCppDisplayThumbnails) {
  const BuiltinOcioConfig builtin;
  const GalleryMaterial material(nav.navigator);
  const Material m = reference().gallery(3)[0].material;
  const int resolution = reference().database().manifest().resolution;
  int width = 0, height = 0;
  ASSERT_EQ(c.navigator_thumbnail_size(nav.navigator, &width, &height), BRDFNAV_OK);
  EXPECT_EQ(width, resolution);
  EXPECT_EQ(height, resolution);

  const std::size_t bytes = std::size_t(resolution) * resolution * 4;
  std::vector<unsigned char> rgba(bytes + 16, 0xab);
  width = height = -1;
  ASSERT_EQ(c.navigator_thumbnail(nav.navigator, &material.c, "sRGB", "Standard", &width, &height,
                                  rgba.data(), rgba.size()),
            BRDFNAV_OK)
      << c.navigator_geterror();
  EXPECT_EQ(width, resolution);
  EXPECT_EQ(height, resolution);
  for (std::size_t i = bytes; i < rgba.size(); ++i) EXPECT_EQ(rgba[i], 0xab) << i;
  rgba.resize(bytes);

  const Thumbnails thumbnails(reference().database(), 0);
  const DisplayThumbnails display(thumbnails);
  const ocio::Thumbnail expected = display.render(m, "sRGB", "Standard");
  ASSERT_EQ(expected.width, resolution);
  EXPECT_EQ(rgba, expected.rgba);
  const Image linear = thumbnails.render(m);
  EXPECT_EQ(rgba, display_encode(linear, true, display.pipeline(), "sRGB", "Standard").rgba);
  // Covered pixels are opaque, the corners (outside the sphere) 0 0 0 0, not over grey; the edge
  // partly covered.
  EXPECT_EQ(rgba[((resolution / 2) * resolution + resolution / 2) * 4 + 3], 255);
  EXPECT_EQ(std::vector<unsigned char>(rgba.begin(), rgba.begin() + 4),
            std::vector<unsigned char>(4, 0));
  int partial = 0;
  for (std::size_t i = 3; i < bytes; i += 4) partial += rgba[i] > 0 && rgba[i] < 255;
  EXPECT_GT(partial, 0);

  // Another view of the same material differs: the view is applied, not ignored.
  std::vector<unsigned char> aces(bytes);
  ASSERT_EQ(c.navigator_thumbnail(nav.navigator, &material.c, "sRGB", "ACES 1.0 SDR-video", &width,
                                  &height, aces.data(), aces.size()),
            BRDFNAV_OK)
      << c.navigator_geterror();
  EXPECT_EQ(aces, display.render(m, "sRGB", "ACES 1.0 SDR-video").rgba);
  EXPECT_NE(aces, rgba);
}

// Bad displays, views, buffers and materials: the error status, a message naming them, and
// nothing written.
TEST_F(CAbiNavigator, ThumbnailsReportBadArgumentsWithoutWriting) {
  const BuiltinOcioConfig builtin;
  const GalleryMaterial material(nav.navigator);
  const int resolution = reference().database().manifest().resolution;
  const std::size_t bytes = std::size_t(resolution) * resolution * 4;
  std::vector<unsigned char> rgba(bytes, 0xab);
  int width = -1, height = -1;
  const auto expect_refused = [&](brdfnav_status status, const std::vector<std::string>& named) {
    EXPECT_EQ(status, BRDFNAV_ERROR_INVALID_ARGUMENT) << named.front();
    for (const std::string& n : named) EXPECT_THAT(c.navigator_geterror(), HasSubstr(n));
    EXPECT_EQ(width, -1);
    EXPECT_EQ(height, -1);
    EXPECT_EQ(rgba, std::vector<unsigned char>(bytes, 0xab));
  };
  expect_refused(c.navigator_thumbnail(nav.navigator, &material.c, "Nonesuch", "Standard", &width,
                                       &height, rgba.data(), bytes),
                 {"display 'Nonesuch'", "'sRGB'", "'Rec.1886'"});
  expect_refused(c.navigator_thumbnail(nav.navigator, &material.c, "sRGB", "Nonesuch", &width,
                                       &height, rgba.data(), bytes),
                 {"display 'sRGB' has no view 'Nonesuch'", "'Standard'", "'ACES 1.0 SDR-video'"});
  expect_refused(c.navigator_thumbnail(nav.navigator, &material.c, "sRGB", "Standard", &width,
                                       &height, rgba.data(), bytes - 1),
                 {"capacity: " + std::to_string(bytes - 1), std::to_string(bytes)});
  expect_refused(c.navigator_thumbnail(nav.navigator, &material.c, "sRGB", "Standard", &width,
                                       &height, nullptr, bytes),
                 {"rgba"});
  expect_refused(c.navigator_thumbnail(nav.navigator, nullptr, "sRGB", "Standard", &width, &height,
                                       rgba.data(), bytes),
                 {"material"});
  expect_refused(c.navigator_thumbnail(nav.navigator, &material.c, nullptr, "Standard", &width,
                                       &height, rgba.data(), bytes),
                 {"display"});
  brdfnav_material acescg = material.c;
  acescg.colorspace = "acescg";
  expect_refused(c.navigator_thumbnail(nav.navigator, &acescg, "sRGB", "Standard", &width, &height,
                                       rgba.data(), bytes),
                 {"colorspace 'acescg'"});
  expect_refused(c.navigator_thumbnail(nullptr, &material.c, "sRGB", "Standard", &width, &height,
                                       rgba.data(), bytes),
                 {"navigator"});
  EXPECT_EQ(c.navigator_thumbnail_size(nav.navigator, &width, nullptr),
            BRDFNAV_ERROR_INVALID_ARGUMENT);
  EXPECT_THAT(c.navigator_geterror(), HasSubstr("height"));
  EXPECT_EQ(width, -1);
}

}  // namespace
}  // namespace brdfnav
