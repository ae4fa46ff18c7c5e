// The C ABIs as a host sees them: dlopen() the built library, check its ABI version first and
// resolve every entry point of its header with dlsym(). api() is libbrdfnav.so (brdfnav.h,
// BRDFNAV_PLUGIN_PATH), navigator_api() libbrdfnav_navigator.so (brdfnav_navigator.h,
// BRDFNAV_NAVIGATOR_PATH, when the test defines it).
#pragma once

#include <brdfnav/brdfnav.h>
#include <dlfcn.h>

#include <stdexcept>
#include <string>

#ifdef BRDFNAV_NAVIGATOR_PATH
#include <brdfnav/brdfnav_navigator.h>
#endif

namespace brdfnav::test {

// Every entry point after the version function, by its name without the brdfnav_ prefix.
// One entry point a line, which clang-format would run together.
// clang-format off
#define BRDFNAV_ENTRY_POINTS(X) \
  X(geterror) \
  X(model_count) \
  X(get_model) \
  X(find_model) \
  X(get_param) \
  X(closure_create) \
  X(closure_load) \
  X(closure_destroy) \
  X(closure_model) \
  X(closure_colorspace) \
  X(closure_eval) \
  X(closure_sample) \
  X(closure_pdf)
#define BRDFNAV_NAVIGATOR_ENTRY_POINTS(X) \
  X(navigator_geterror) \
  X(navigator_open) \
  X(navigator_close) \
  X(navigator_neighbors) \
  X(navigator_neighbors_load) \
  X(navigator_gallery) \
  X(neighbors_count) \
  X(neighbors_get) \
  X(neighbors_free) \
  X(navigator_displays) \
  X(navigator_display) \
  X(navigator_views) \
  X(navigator_view) \
  X(navigator_thumbnail_size) \
  X(navigator_thumbnail)
// clang-format on

#define BRDFNAV_DECLARE(name) decltype(&::brdfnav_##name) name = nullptr;
struct Api {
  BRDFNAV_ENTRY_POINTS(BRDFNAV_DECLARE)
};
#ifdef BRDFNAV_NAVIGATOR_PATH
struct NavigatorApi {
  BRDFNAV_NAVIGATOR_ENTRY_POINTS(BRDFNAV_DECLARE)
};
#endif
#undef BRDFNAV_DECLARE

template <typename Function>
Function resolve(void* library, const char* name) {
  auto* symbol = reinterpret_cast<Function>(dlsym(library, name));
  if (!symbol) throw std::runtime_error(std::string("missing symbol ") + name);
  return symbol;
}

// dlopen()s `path` as a host would and checks its version function against `expected`; throws
// with the reason when a host would refuse the library.
inline void* open_library(const char* path, const char* version_function, int expected) {
  void* library = dlopen(path, RTLD_NOW | RTLD_LOCAL);
  if (!library) throw std::runtime_error(std::string("dlopen: ") + dlerror());
  const int version = resolve<int (*)()>(library, version_function)();
  if (version != expected)
    throw std::runtime_error(std::string(path) + ": ABI version " + std::to_string(version) +
                             ", expected " + std::to_string(expected));
  return library;
}

#define BRDFNAV_RESOLVE(name) a.name = resolve<decltype(a.name)>(library, "brdfnav_" #name);

// Loads libbrdfnav.so once per process.
inline const Api& api() {
  static const Api loaded = [] {
    void* library = open_library(BRDFNAV_PLUGIN_PATH, "brdfnav_abi_version", BRDFNAV_ABI_VERSION);
    Api a;
    BRDFNAV_ENTRY_POINTS(BRDFNAV_RESOLVE)
    return a;
  }();
  return loaded;
}

#ifdef BRDFNAV_NAVIGATOR_PATH
// Loads libbrdfnav_navigator.so once per process.
inline const NavigatorApi& navigator_api() {
  static const NavigatorApi loaded = [] {
    void* library = open_library(BRDFNAV_NAVIGATOR_PATH, "brdfnav_navigator_abi_version",
                                 BRDFNAV_NAVIGATOR_ABI_VERSION);
    NavigatorApi a;
    BRDFNAV_NAVIGATOR_ENTRY_POINTS(BRDFNAV_RESOLVE)
    return a;
  }();
  return loaded;
}
#endif

#undef BRDFNAV_RESOLVE

}  // namespace brdfnav::test
