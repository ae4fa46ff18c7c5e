// The C ABI of brdfnav.h over the C++ core and navigator. Every entry point runs its body inside
// guarded(), the one place that turns C++ exceptions into a status code and a per-thread message.
#include <brdfnav/brdfnav.h>

#include <brdfnav/core/material.h>
#include <brdfnav/io/material_yaml.h>
#include <brdfnav/navigator.h>

#include <array>
#include <cstring>
#include <memory>
#include <new>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

struct brdfnav_closure {
  brdfnav::Material material;
  brdfnav::Closure closure;
};

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

// A failure the ABI reports with a specific status (argument checks).
class AbiError : public std::runtime_error {
 public:
  AbiError(brdfnav_status status, const std::string& what)
      : std::runtime_error(what), status_(status) {}
  brdfnav_status status() const { return status_; }

 private:
  brdfnav_status status_;
};

thread_local std::string last_error;
thread_local bool last_error_lost = false;

brdfnav_status fail(brdfnav_status status, const char* message) noexcept {
  try {
    last_error = message;
    last_error_lost = false;
  } catch (...) {  // no memory for the message: brdfnav_geterror() says so instead
    last_error_lost = true;
  }
  return status;
}

template <typename Body>
brdfnav_status guarded(Body&& body) noexcept {
  try {
    body();
    return BRDFNAV_OK;
  } catch (const AbiError& e) {
    return fail(e.status(), e.what());
  } catch (const MaterialFileError& e) {
    return fail(BRDFNAV_ERROR_IO, e.what());
  } catch (const MaterialError& e) {
    return fail(BRDFNAV_ERROR_PARSE, e.what());
  } catch (const DatabaseError& e) {
    return fail(BRDFNAV_ERROR_DATABASE, e.what());
  } catch (const NavigatorError& e) {
    return fail(BRDFNAV_ERROR_INVALID_ARGUMENT, e.what());
  } catch (const std::bad_alloc&) {
    return fail(BRDFNAV_ERROR_OUT_OF_MEMORY, "out of memory");
  } catch (const std::exception& e) {
    return fail(BRDFNAV_ERROR_INTERNAL, e.what());
  } catch (...) {
    return fail(BRDFNAV_ERROR_INTERNAL, "unknown internal error");
  }
}

void require(const void* pointer, const char* name) {
  if (!pointer) throw AbiError(BRDFNAV_ERROR_INVALID_ARGUMENT, std::string(name) + " is NULL");
}

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

const ModelInfo& model_at(int model) {
  if (model < 0 || model >= kModelCount)
    throw AbiError(BRDFNAV_ERROR_INVALID_ARGUMENT, "model index " + std::to_string(model) +
                                                       " is outside [0, " +
                                                       std::to_string(kModelCount) + ")");
  return brdfnav::models()[model];
}

// The names and descriptions as NUL-terminated strings (the tables hold string_views).
struct CStrings {
  struct Model {
    std::string name, title;
    std::vector<std::array<std::string, 3>> params;  // name, unit, description
  };
  std::vector<Model> models;

  static const CStrings& get() {
    static const CStrings strings = build();
    return strings;
  }

 private:
  static CStrings build() {
    CStrings s;
    for (const ModelInfo& m : brdfnav::models()) {
      Model& model = s.models.emplace_back(Model{std::string(m.name), std::string(m.title), {}});
      for (const ParamSpec& p : m.params)
        model.params.push_back(
            {std::string(p.name), std::string(p.unit), std::string(p.description)});
    }
    return s;
  }
};

Material material_from_struct(const brdfnav_material& desc) {
  require(desc.model, "material->model");
  const ModelInfo* info = find_model(desc.model);
  if (!info)
    throw AbiError(BRDFNAV_ERROR_INVALID_ARGUMENT,
                   "material->model: unknown model '" + std::string(desc.model) + "'");
  Material m = default_material(info->id);
  if (desc.param_count > 0) require(desc.params, "material->params");
  std::vector<bool> given(info->params.size(), false);
  for (std::size_t i = 0; i < desc.param_count; ++i) {
    const brdfnav_param_value& p = desc.params[i];
    require(p.name, "material->params[i].name");
    const int index = find_param(*info, p.name);
    if (index < 0 || given[index])
      throw AbiError(BRDFNAV_ERROR_INVALID_ARGUMENT,
                     "material->params: parameter '" + std::string(p.name) +
                         (index < 0 ? "' is not one of model '" + std::string(info->name) + "'"
                                    : "' is given twice"));
    given[index] = true;
    m.params[index] = p.value;
  }
  m.rho_d = Rgb(desc.rho_d[0], desc.rho_d[1], desc.rho_d[2]);
  m.rho_s = Rgb(desc.rho_s[0], desc.rho_s[1], desc.rho_s[2]);
  if (desc.colorspace) m.colorspace = desc.colorspace;
  try {
    validate(m);
  } catch (const MaterialError& e) {
    throw AbiError(BRDFNAV_ERROR_INVALID_ARGUMENT, std::string("material: ") + e.what());
  }
  return m;
}

brdfnav_closure* new_closure(Material m) {
  Closure closure = make_closure(m);
  return new brdfnav_closure{std::move(m), std::move(closure)};
}

// A unit vector from three doubles.
Vec3 direction(const double* w, const char* name) {
  require(w, name);
  const Vec3 v(w[0], w[1], w[2]);
  if (!v.allFinite())
    throw AbiError(BRDFNAV_ERROR_INVALID_ARGUMENT, std::string(name) + " is not finite");
  const std::optional<Vec3> unit = unit_direction(v);
  if (!unit)
    throw AbiError(BRDFNAV_ERROR_INVALID_ARGUMENT, std::string(name) + " is the zero vector");
  return *unit;
}

double unit_random(double u, const char* name) {
  if (!(u >= 0 && u < 1))
    throw AbiError(BRDFNAV_ERROR_INVALID_ARGUMENT,
                   std::string(name) + " = " + std::to_string(u) + " is outside [0, 1)");
  return u;
}

template <typename Vector3>
void copy3(const Vector3& from, double to[3]) {
  for (int i = 0; i < 3; ++i) to[i] = from[i];
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
    return new_list(query(navigator->navigator));
  });
}

}  // namespace

extern "C" {

int brdfnav_abi_version(void) {
  return BRDFNAV_ABI_VERSION;
}

const char* brdfnav_geterror(void) {
  return last_error_lost ? "out of memory while recording an error" : last_error.c_str();
}

int brdfnav_model_count(void) {
  return kModelCount;
}

brdfnav_status brdfnav_get_model(int model, brdfnav_model_desc* out) {
  return guarded([&] {
    const ModelInfo& info = model_at(model);
    require(out, "out");
    const CStrings::Model& s = CStrings::get().models[model];
    *out = {s.name.c_str(), s.title.c_str(), static_cast<int>(info.params.size()),
            info.has_mirror ? 1 : 0};
  });
}

brdfnav_status brdfnav_find_model(const char* name, int* model) {
  return guarded([&] {
    require(name, "name");
    require(model, "model");
    const ModelInfo* info = brdfnav::find_model(name);
    if (!info)
      throw AbiError(BRDFNAV_ERROR_INVALID_ARGUMENT, "unknown model '" + std::string(name) + "'");
    *model = static_cast<int>(info->id);
  });
}

brdfnav_status brdfnav_get_param(int model, int param, brdfnav_param_desc* out) {
  return guarded([&] {
    const ModelInfo& info = model_at(model);
    if (param < 0 || param >= static_cast<int>(info.params.size()))
      throw AbiError(BRDFNAV_ERROR_INVALID_ARGUMENT,
                     "parameter index " + std::to_string(param) + " is outside [0, " +
                         std::to_string(info.params.size()) + ") for model '" +
                         std::string(info.name) + "'");
    require(out, "out");
    const ParamSpec& p = info.params[param];
    const auto& s = CStrings::get().models[model].params[param];
    *out = {s[0].c_str(),
            s[1].c_str(),
            s[2].c_str(),
            p.valid_min,
            p.valid_max,
            p.default_value,
            p.grid_min,
            p.grid_max,
            p.grid_count,
            p.scale == Scale::log ? BRDFNAV_SCALE_LOG : BRDFNAV_SCALE_LINEAR,
            p.nodes.empty() ? nullptr : p.nodes.data(),
            p.nodes.size()};
  });
}

brdfnav_status brdfnav_closure_create(const brdfnav_material* material, brdfnav_closure** out) {
  return create_into(out, [&] {
    require(material, "material");
    return new_closure(material_from_struct(*material));
  });
}

brdfnav_status brdfnav_closure_load(const char* path_or_spec, brdfnav_closure** out) {
  return create_into(out, [&] {
    require(path_or_spec, "path_or_spec");
    return new_closure(load_material(path_or_spec));
  });
}

void brdfnav_closure_destroy(brdfnav_closure* closure) {
  delete closure;
}

brdfnav_status brdfnav_closure_model(const brdfnav_closure* closure, int* model) {
  return guarded([&] {
    require(closure, "closure");
    require(model, "model");
    *model = static_cast<int>(closure->material.model);
  });
}

brdfnav_status brdfnav_closure_colorspace(const brdfnav_closure* closure, const char** colorspace) {
  return guarded([&] {
    require(closure, "closure");
    require(colorspace, "colorspace");
    *colorspace = closure->material.colorspace.c_str();
  });
}

brdfnav_status brdfnav_closure_eval(const brdfnav_closure* closure, const double wi[3],
                                    const double wo[3], double f[3]) {
  return guarded([&] {
    require(closure, "closure");
    require(f, "f");
    copy3(closure->closure.eval(direction(wi, "wi"), direction(wo, "wo")), f);
  });
}

brdfnav_status brdfnav_closure_sample(const brdfnav_closure* closure, const double wo[3], double uc,
                                      double u1, double u2, brdfnav_sample* out) {
  return guarded([&] {
    require(closure, "closure");
    require(out, "out");
    const Vec3 w = direction(wo, "wo");
    const Vec2 u(unit_random(u1, "u1"), unit_random(u2, "u2"));
    const auto s = closure->closure.sample(w, unit_random(uc, "uc"), u);
    brdfnav_sample result{};
    if (s) {
      result.sampled = 1;
      result.is_delta = s->delta ? 1 : 0;
      copy3(s->wi, result.wi);
      copy3(s->f, result.f);
      result.pdf = s->pdf;
    }
    *out = result;
  });
}

brdfnav_status brdfnav_closure_pdf(const brdfnav_closure* closure, const double wi[3],
                                   const double wo[3], double* pdf) {
  return guarded([&] {
    require(closure, "closure");
    require(pdf, "pdf");
    *pdf = closure->closure.pdf(direction(wi, "wi"), direction(wo, "wo"));
  });
}

brdfnav_status brdfnav_navigator_open(const char* database_dir, brdfnav_navigator** out) {
  return create_into(out, [&] {
    require(database_dir, "database_dir");
    return new brdfnav_navigator{Navigator::open(database_dir)};
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
                   (n.clamped ? BRDFNAV_NEIGHBOR_CLAMPED : 0u);
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
