// The C ABI of brdfnav_navigator.h over the C++ navigator. Every entry point runs its body inside
// guarded() (brdfnav/io/c_abi.h), which reports any brdfnav::Error by its code.
#include <brdfnav/brdfnav_navigator.h>

#include <brdfnav/io/c_abi.h>
#include <brdfnav/io/material_yaml.h>
#include <brdfnav/navigator/display_thumbnails.h>
#include <brdfnav/navigator/navigator.h>
#include <brdfnav/navigator/thumbnails.h>

#include <algorithm>
#include <cstring>
#include <memory>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

struct brdfnav_navigator {
  // The display thumbnails at the database's resolution, and the config's displays and views as
  // the C strings the ABI hands out. Made by the first call that needs them (colour_of()): a host
  // that only navigates never loads an OCIO config.
  struct Color {
    explicit Color(const brdfnav::Database& database)
        : thumbnails(database, 0), display(thumbnails) {
      for (std::string& d : display.pipeline().displays()) {
        views.push_back(display.pipeline().views(d));
        displays.push_back(std::move(d));
      }
    }
    brdfnav::Thumbnails thumbnails;
    brdfnav::DisplayThumbnails display;
    std::vector<std::string> displays;
    std::vector<std::vector<std::string>> views;  // views[i]: those of displays[i]
  };

  explicit brdfnav_navigator(brdfnav::Navigator n) : navigator(std::move(n)) {}

  brdfnav::Navigator navigator;
  mutable std::mutex color_mutex;
  mutable std::unique_ptr<const Color> color;  // set once, then immutable
};

struct brdfnav_neighbors {
  struct Entry {
    brdfnav::Neighbor neighbor;
    std::vector<brdfnav_param_value> params;  // names point into the library's static strings
  };
  std::vector<Entry> entries;
};

namespace {

using namespace brdfnav;
using namespace brdfnav::abi;

static_assert(BRDFNAV_TAB_LOBE == int(Tab::lobe) && BRDFNAV_TAB_DIFFUSE == int(Tab::diffuse) &&
              BRDFNAV_TAB_SPECULAR == int(Tab::specular) &&
              BRDFNAV_TAB_MODELS == int(Tab::models) && BRDFNAV_TAB_GALLERY == int(Tab::gallery));

// A C host may pass any int as a brdfnav_tab (a C enum is an int), but in C++ loading an enum
// outside its range is undefined (UBSan, ./run check): the value is read from its bytes.
Tab tab_of(const brdfnav_tab& tab) {
  int value = 0;
  static_assert(sizeof value == sizeof tab);
  std::memcpy(&value, &tab, sizeof value);
  if (value < 0 || value >= static_cast<int>(std::size(kTabs)))
    throw Error(ErrorCode::invalid_argument,
                "tab " + std::to_string(value) + " is not a brdfnav_tab");
  return kTabs[value];
}

brdfnav_neighbors* new_list(std::vector<Neighbor> neighbors) {
  auto list = std::make_unique<brdfnav_neighbors>();
  for (Neighbor& n : neighbors) {
    const auto model = static_cast<std::size_t>(n.material.model);
    std::vector<brdfnav_param_value> params;
    for (std::size_t i = 0; i < n.material.params.size(); ++i)
      params.push_back({CStrings::get().models[model].params[i][0].c_str(), n.material.params[i]});
    list->entries.push_back({std::move(n), std::move(params)});
  }
  return list.release();
}

// A query of `navigator` whose neighbours become a new list in *out.
template <typename Query>
brdfnav_status list_query(const brdfnav_navigator* navigator, brdfnav_neighbors** out,
                          Query&& query) {
  return create_into(out, [&] {
    require(navigator, "navigator");
    return new_list(query(navigator->navigator));
  });
}

using Color = brdfnav_navigator::Color;

// The navigator's display thumbnails, made on first use. A config that does not load is the
// host's environment ($OCIO), not a bad argument (ColorError, ErrorCode::io: BRDFNAV_ERROR_IO),
// and the next call tries again.
const Color& color_of(const brdfnav_navigator* navigator) {
  require(navigator, "navigator");
  std::lock_guard lock(navigator->color_mutex);
  if (!navigator->color)
    navigator->color = std::make_unique<const Color>(navigator->navigator.database());
  return *navigator->color;
}

// The views of `display`, one of the config's.
const std::vector<std::string>& views_of(const Color& color, const char* display) {
  require(display, "display");
  color.display.pipeline().views(display);  // an unknown display: ErrorCode::invalid_argument
  const auto it = std::find(color.displays.begin(), color.displays.end(), display);
  return color.views[static_cast<std::size_t>(it - color.displays.begin())];
}

// Error(invalid_argument) unless `index` < `count`; `what` names the list.
void require_index(std::size_t index, std::size_t count, const std::string& what) {
  if (index >= count)
    throw Error(ErrorCode::invalid_argument, what + " index " + std::to_string(index) +
                                                 " is outside [0, " + std::to_string(count) + ")");
}

// A material the thumbnails can show: in the database's colour space, of a model it holds (as
// the navigator's queries require).
void check_thumbnail_material(const Database& database, const Material& m) {
  require_render_colorspace(m);
  if (!database.embedding(m.model))
    throw Error(ErrorCode::invalid_argument, database.dir().string() + ": holds no model '" +
                                                 std::string(model_info(m.model).name) + "'");
}

}  // namespace

extern "C" {

int brdfnav_navigator_abi_version(void) {
  return BRDFNAV_NAVIGATOR_ABI_VERSION;
}

const char* brdfnav_navigator_geterror(void) {
  return last_error();
}

brdfnav_status brdfnav_navigator_open(const char* database_dir, brdfnav_navigator** out) {
  return create_into(out, [&] {
    require(database_dir, "database_dir");
    return new brdfnav_navigator(Navigator::open(database_dir));
  });
}

void brdfnav_navigator_close(brdfnav_navigator* navigator) {
  delete navigator;
}

brdfnav_status brdfnav_navigator_neighbors(const brdfnav_navigator* navigator,
                                           const brdfnav_material* current, double radius,
                                           brdfnav_tab tab, int clusters, brdfnav_neighbors** out) {
  return list_query(navigator, out, [&](const Navigator& nav) {
    require(current, "current");
    return nav.neighbors(material_from_struct(*current), radius, tab_of(tab), clusters);
  });
}

brdfnav_status brdfnav_navigator_neighbors_load(const brdfnav_navigator* navigator,
                                                const char* path_or_spec, double radius,
                                                brdfnav_tab tab, int clusters,
                                                brdfnav_neighbors** out) {
  return list_query(navigator, out, [&](const Navigator& nav) {
    require(path_or_spec, "path_or_spec");
    return nav.neighbors(load_material(path_or_spec), radius, tab_of(tab), clusters);
  });
}

brdfnav_status brdfnav_navigator_gallery(const brdfnav_navigator* navigator, int count,
                                         brdfnav_neighbors** out) {
  return list_query(navigator, out, [&](const Navigator& nav) { return nav.gallery(count); });
}

brdfnav_status brdfnav_neighbors_count(const brdfnav_neighbors* list, size_t* count) {
  return guarded([&] {
    require(list, "list");
    require(count, "count");
    *count = list->entries.size();
  });
}

brdfnav_status brdfnav_neighbors_get(const brdfnav_neighbors* list, size_t index,
                                     brdfnav_neighbor* out) {
  return guarded([&] {
    require(list, "list");
    require_index(index, list->entries.size(), "neighbour");
    require(out, "out");
    const brdfnav_neighbors::Entry& e = list->entries[index];
    const Neighbor& n = e.neighbor;
    const Material& m = n.material;
    brdfnav_neighbor result{};
    result.tab = static_cast<brdfnav_tab>(n.tab);
    result.label = n.label.c_str();
    result.distance = n.distance;
    result.flags = (n.at_boundary ? BRDFNAV_NEIGHBOR_AT_BOUNDARY : 0u) |
                   (n.clamped ? BRDFNAV_NEIGHBOR_CLAMPED : 0u) |
                   (n.beyond_radius ? BRDFNAV_NEIGHBOR_BEYOND_RADIUS : 0u);
    result.words = n.words.c_str();
    result.change = n.change.c_str();
    result.opposite = n.opposite;
    result.material.model = CStrings::get().models[static_cast<std::size_t>(m.model)].name.c_str();
    result.material.params = e.params.data();
    result.material.param_count = e.params.size();
    copy3(m.rho_d, result.material.rho_d);
    copy3(m.rho_s, result.material.rho_s);
    result.material.colorspace = m.colorspace.c_str();
    *out = result;
  });
}

void brdfnav_neighbors_free(brdfnav_neighbors* list) {
  delete list;
}

brdfnav_status brdfnav_navigator_displays(const brdfnav_navigator* navigator, size_t* count) {
  return guarded([&] {
    const Color& color = color_of(navigator);
    require(count, "count");
    *count = color.displays.size();
  });
}

brdfnav_status brdfnav_navigator_display(const brdfnav_navigator* navigator, size_t index,
                                         const char** name) {
  return guarded([&] {
    const Color& color = color_of(navigator);
    require_index(index, color.displays.size(), "display");
    require(name, "name");
    *name = color.displays[index].c_str();
  });
}

brdfnav_status brdfnav_navigator_views(const brdfnav_navigator* navigator, const char* display,
                                       size_t* count) {
  return guarded([&] {
    const std::vector<std::string>& views = views_of(color_of(navigator), display);
    require(count, "count");
    *count = views.size();
  });
}

brdfnav_status brdfnav_navigator_view(const brdfnav_navigator* navigator, const char* display,
                                      size_t index, const char** name) {
  return guarded([&] {
    const std::vector<std::string>& views = views_of(color_of(navigator), display);
    require_index(index, views.size(), "view");
    require(name, "name");
    *name = views[index].c_str();
  });
}

brdfnav_status brdfnav_navigator_thumbnail_size(const brdfnav_navigator* navigator, int* width,
                                                int* height) {
  return guarded([&] {
    require(navigator, "navigator");
    require(width, "width");
    require(height, "height");
    // What Thumbnails(database, 0) renders at, without loading the OCIO config.
    *width = *height = navigator->navigator.database().manifest().resolution;
  });
}

brdfnav_status brdfnav_navigator_thumbnail(const brdfnav_navigator* navigator,
                                           const brdfnav_material* material, const char* display,
                                           const char* view, int* width, int* height,
                                           unsigned char* rgba, size_t capacity) {
  return guarded([&] {
    require(navigator, "navigator");
    require(material, "material");
    require(display, "display");
    require(view, "view");
    require(width, "width");
    require(height, "height");
    require(rgba, "rgba");
    const Material m = material_from_struct(*material);
    check_thumbnail_material(navigator->navigator.database(), m);
    const Color& color = color_of(navigator);
    color.display.pipeline().validate(display, view);
    const int size = color.display.resolution();
    const std::size_t needed = std::size_t(size) * std::size_t(size) * 4;
    if (capacity < needed)
      throw Error(ErrorCode::invalid_argument,
                  "capacity: " + std::to_string(capacity) + " bytes, but the thumbnail needs " +
                      std::to_string(size) + " x " + std::to_string(size) +
                      " x 4 = " + std::to_string(needed));
    // A processor the config cannot build is ErrorCode::io (the host's environment).
    const ocio::Thumbnail t = color.display.render(m, display, view);
    if (t.rgba.size() != needed)
      throw Error(ErrorCode::internal, "a thumbnail of " + std::to_string(t.rgba.size()) +
                                           " bytes, not " + std::to_string(needed));
    std::memcpy(rgba, t.rgba.data(), needed);
    *width = t.width;
    *height = t.height;
  });
}

}  // extern "C"
