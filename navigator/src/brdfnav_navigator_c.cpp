// The C ABI of brdfnav_navigator.h over the C++ navigator. Every entry point runs its body inside
// guarded() (brdfnav/io/c_abi.h); the navigator's own errors are translated at this edge.
#include <brdfnav/brdfnav_navigator.h>

#include <brdfnav/io/c_abi.h>
#include <brdfnav/io/material_yaml.h>
#include <brdfnav/navigator/navigator.h>

#include <cstring>
#include <memory>
#include <string>
#include <vector>

struct brdfnav_navigator {
  brdfnav::Navigator navigator;
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

// Runs `body`, turning the navigator's and the database's errors into the ABI's statuses.
template <typename Body>
auto translated(Body&& body) -> decltype(body()) {
  try {
    return body();
  } catch (const DatabaseError& e) {
    throw AbiError(BRDFNAV_ERROR_DATABASE, e.what());
  } catch (const NavigatorError& e) {
    throw AbiError(BRDFNAV_ERROR_INVALID_ARGUMENT, e.what());
  }
}

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
    throw AbiError(BRDFNAV_ERROR_INVALID_ARGUMENT,
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
    return new_list(translated([&] { return query(navigator->navigator); }));
  });
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
    return translated([&] { return new brdfnav_navigator{Navigator::open(database_dir)}; });
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
    if (index >= list->entries.size())
      throw AbiError(BRDFNAV_ERROR_INVALID_ARGUMENT,
                     "neighbour index " + std::to_string(index) + " is outside [0, " +
                         std::to_string(list->entries.size()) + ")");
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

}  // extern "C"
