// libbrdfnav.so as a host sees it: dlopen() the built library (BRDFNAV_PLUGIN_PATH), check the
// ABI version first and resolve every entry point of brdfnav.h with dlsym().
#pragma once

#include <brdfnav/brdfnav.h>
#include <dlfcn.h>

#include <stdexcept>
#include <string>

namespace brdfnav::test {

// Every entry point after brdfnav_abi_version, by its name without the brdfnav_ prefix.
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
  X(closure_pdf) \
  X(navigator_open) \
  X(navigator_close) \
  X(navigator_neighbors) \
  X(navigator_neighbors_load) \
  X(navigator_gallery) \
  X(neighbors_count) \
  X(neighbors_get) \
  X(neighbors_free)
// clang-format on

struct Api {
#define BRDFNAV_DECLARE(name) decltype(&::brdfnav_##name) name = nullptr;
  BRDFNAV_ENTRY_POINTS(BRDFNAV_DECLARE)
#undef BRDFNAV_DECLARE
};

template <typename Function>
Function resolve(void* library, const char* name) {
  auto* symbol = reinterpret_cast<Function>(dlsym(library, name));
  if (!symbol) throw std::runtime_error(std::string("missing symbol ") + name);
  return symbol;
}

// Loads the library once per process; throws with the reason when a host would refuse it.
inline const Api& api() {
  static const Api loaded = [] {
    void* library = dlopen(BRDFNAV_PLUGIN_PATH, RTLD_NOW | RTLD_LOCAL);
    if (!library) throw std::runtime_error(std::string("dlopen: ") + dlerror());
    const auto abi_version =
        resolve<decltype(&::brdfnav_abi_version)>(library, "brdfnav_abi_version");
    if (abi_version() != BRDFNAV_ABI_VERSION)
      throw std::runtime_error("ABI version " + std::to_string(abi_version()) + ", expected " +
                               std::to_string(BRDFNAV_ABI_VERSION));
    Api a;
#define BRDFNAV_RESOLVE(name) a.name = resolve<decltype(a.name)>(library, "brdfnav_" #name);
    BRDFNAV_ENTRY_POINTS(BRDFNAV_RESOLVE)
#undef BRDFNAV_RESOLVE
    return a;
  }();
  return loaded;
}

}  // namespace brdfnav::test
