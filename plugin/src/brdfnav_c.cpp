// The C ABI of brdfnav.h over the C++ core: closures, the models' tables and the material
// format. Every entry point runs its body inside guarded() (brdfnav/io/c_abi.h), the one place
// that turns C++ exceptions into a status code and a per-thread message.
#include <brdfnav/brdfnav.h>

#include <brdfnav/core/material.h>
#include <brdfnav/io/c_abi.h>
#include <brdfnav/io/material_yaml.h>

#include <optional>
#include <string>

struct brdfnav_closure {
  brdfnav::Material material;
  brdfnav::Closure closure;
};

namespace {

using namespace brdfnav;
using namespace brdfnav::abi;

const ModelInfo& model_at(int model) {
  if (model < 0 || model >= kModelCount)
    throw Error(ErrorCode::invalid_argument, "model index " + std::to_string(model) +
                                                 " is outside [0, " + std::to_string(kModelCount) +
                                                 ")");
  return brdfnav::models()[model];
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
    throw Error(ErrorCode::invalid_argument, std::string(name) + " is not finite");
  const std::optional<Vec3> unit = unit_direction(v);
  if (!unit) throw Error(ErrorCode::invalid_argument, std::string(name) + " is the zero vector");
  return *unit;
}

double unit_random(double u, const char* name) {
  if (!(u >= 0 && u < 1))
    throw Error(ErrorCode::invalid_argument,
                std::string(name) + " = " + std::to_string(u) + " is outside [0, 1)");
  return u;
}

}  // namespace

extern "C" {

int brdfnav_abi_version(void) {
  return BRDFNAV_ABI_VERSION;
}

const char* brdfnav_geterror(void) {
  return last_error();
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
      throw Error(ErrorCode::invalid_argument, "unknown model '" + std::string(name) + "'");
    *model = static_cast<int>(info->id);
  });
}

brdfnav_status brdfnav_get_param(int model, int param, brdfnav_param_desc* out) {
  return guarded([&] {
    const ModelInfo& info = model_at(model);
    if (param < 0 || param >= static_cast<int>(info.params.size()))
      throw Error(ErrorCode::invalid_argument, "parameter index " + std::to_string(param) +
                                                   " is outside [0, " +
                                                   std::to_string(info.params.size()) +
                                                   ") for model '" + std::string(info.name) + "'");
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

}  // extern "C"
