// What the C ABIs of brdfnav (libbrdfnav.so, brdfnav.h; libbrdfnav_navigator.so,
// brdfnav_navigator.h) share: the one place that turns C++ exceptions into a status and a
// per-thread message (brdfnav::Error's code onto brdfnav_status), argument checks, and the
// conversions between the C structs and the core's types. Linked statically into each library,
// so each keeps its own last error.
#pragma once

#include <brdfnav/brdfnav.h>
#include <brdfnav/core/material.h>

#include <array>
#include <string>
#include <vector>

namespace brdfnav::abi {

// The status an Error of `code` is reported with.
brdfnav_status status_of(ErrorCode code) noexcept;

// The status of the exception being handled (call inside a catch block only), recorded as the
// calling thread's last error.
brdfnav_status fail_current() noexcept;
// The calling thread's last error message ("" if none).
const char* last_error() noexcept;

// Runs `body`; BRDFNAV_OK, or the status of what it threw (with its message recorded).
template <typename Body>
brdfnav_status guarded(Body&& body) noexcept {
  try {
    body();
    return BRDFNAV_OK;
  } catch (...) {
    return fail_current();
  }
}

// Error(invalid_argument, "NAME is NULL") for a null pointer.
void require(const void* pointer, const char* name);

// The functions that create an object: *out is NULL unless `make` (argument checks, then the
// new object) succeeds.
template <typename T, typename Make>
brdfnav_status create_into(T** out, Make&& make) noexcept {
  if (out) *out = nullptr;
  return guarded([&] {
    require(out, "out");
    *out = make();
  });
}

// A material from its C struct; Error(invalid_argument) naming the field that is wrong.
Material material_from_struct(const brdfnav_material& desc);

// The names and descriptions of the models' tables as NUL-terminated strings that live as long
// as the library (the tables hold string_views).
struct CStrings {
  struct Model {
    std::string name, title;
    std::vector<std::array<std::string, 3>> params;  // name, unit, description
  };
  std::vector<Model> models;

  static const CStrings& get();
};

template <typename Vector3>
void copy3(const Vector3& from, double to[3]) {
  for (int i = 0; i < 3; ++i) to[i] = from[i];
}

}  // namespace brdfnav::abi
