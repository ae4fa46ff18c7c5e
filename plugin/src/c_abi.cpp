#include <brdfnav/io/c_abi.h>

#include <brdfnav/io/material_yaml.h>

#include <new>

namespace brdfnav::abi {

namespace {

thread_local std::string last_message;
thread_local bool last_message_lost = false;

brdfnav_status fail(brdfnav_status status, const char* message) noexcept {
  try {
    last_message = message;
    last_message_lost = false;
  } catch (...) {  // no memory for the message: last_error() says so instead
    last_message_lost = true;
  }
  return status;
}

CStrings build_strings() {
  CStrings s;
  for (const ModelInfo& m : brdfnav::models()) {
    CStrings::Model& model =
        s.models.emplace_back(CStrings::Model{std::string(m.name), std::string(m.title), {}});
    for (const ParamSpec& p : m.params)
      model.params.push_back(
          {std::string(p.name), std::string(p.unit), std::string(p.description)});
  }
  return s;
}

}  // namespace

brdfnav_status status_of(ErrorCode code) noexcept {
  switch (code) {
    case ErrorCode::invalid_argument:
      return BRDFNAV_ERROR_INVALID_ARGUMENT;
    case ErrorCode::parse:
      return BRDFNAV_ERROR_PARSE;
    case ErrorCode::io:
      return BRDFNAV_ERROR_IO;
    case ErrorCode::database:
      return BRDFNAV_ERROR_DATABASE;
    case ErrorCode::internal:
      return BRDFNAV_ERROR_INTERNAL;
  }
  return BRDFNAV_ERROR_INTERNAL;
}

brdfnav_status fail_current() noexcept {
  try {
    throw;
  } catch (const Error& e) {
    return fail(status_of(e.code()), e.what());
  } catch (const std::bad_alloc&) {
    return fail(BRDFNAV_ERROR_OUT_OF_MEMORY, "out of memory");
  } catch (const std::exception& e) {
    return fail(BRDFNAV_ERROR_INTERNAL, e.what());
  } catch (...) {
    return fail(BRDFNAV_ERROR_INTERNAL, "unknown internal error");
  }
}

const char* last_error() noexcept {
  return last_message_lost ? "out of memory while recording an error" : last_message.c_str();
}

void require(const void* pointer, const char* name) {
  if (!pointer) throw Error(ErrorCode::invalid_argument, std::string(name) + " is NULL");
}

const CStrings& CStrings::get() {
  static const CStrings strings = build_strings();
  return strings;
}

Material material_from_struct(const brdfnav_material& desc) {
  require(desc.model, "material->model");
  const ModelInfo* info = find_model(desc.model);
  if (!info)
    throw Error(ErrorCode::invalid_argument,
                "material->model: unknown model '" + std::string(desc.model) + "'");
  Material m = default_material(info->id);
  if (desc.param_count > 0) require(desc.params, "material->params");
  std::vector<bool> given(info->params.size(), false);
  for (std::size_t i = 0; i < desc.param_count; ++i) {
    const brdfnav_param_value& p = desc.params[i];
    require(p.name, "material->params[i].name");
    const int index = find_param(*info, p.name);
    if (index < 0 || given[index])
      throw Error(ErrorCode::invalid_argument,
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
    throw Error(ErrorCode::invalid_argument, "material", e.what());
  }
  return m;
}

}  // namespace brdfnav::abi
