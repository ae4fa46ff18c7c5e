#include <brdfnav/core/material.h>

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <sstream>

namespace brdfnav {

namespace {

std::string fmt(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

void check_rgb(const Rgb& c, double max, const char* key) {
  for (int i = 0; i < 3; ++i) {
    if (!std::isfinite(c[i]) || c[i] < 0 || c[i] > max)
      throw MaterialError(std::string(key) + ": component " + std::to_string(i) + " = " +
                          fmt(c[i]) + " is outside [0, " + fmt(max) + "]");
  }
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

double parse_number(std::string_view text, std::string_view key) {
  text = trim(text);
  double v = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc() || end != text.data() + text.size() || text.empty())
    throw MaterialError("key '" + std::string(key) + "': '" + std::string(text) +
                        "' is not a number");
  if (!std::isfinite(v))
    throw MaterialError("key '" + std::string(key) + "': value must be finite");
  return v;
}

// "0.2" is grey; "0.2/0.3/0.4" is RGB.
Rgb parse_color(std::string_view text, std::string_view key) {
  std::vector<std::string_view> parts;
  std::size_t start = 0;
  for (std::size_t slash; (slash = text.find('/', start)) != std::string_view::npos;
       start = slash + 1)
    parts.push_back(text.substr(start, slash - start));
  parts.push_back(text.substr(start));
  if (parts.size() == 1) return Rgb::Constant(parse_number(parts[0], key));
  if (parts.size() != 3)
    throw MaterialError("key '" + std::string(key) + "': expected one value or r/g/b, got '" +
                        std::string(text) + "'");
  return {parse_number(parts[0], key), parse_number(parts[1], key), parse_number(parts[2], key)};
}

// The code point that starts at s[i], advancing i past it; -1 where the bytes are not valid,
// shortest-form UTF-8.
long decode_utf8(std::string_view s, std::size_t& i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
  const unsigned char lead = byte(i);
  if (lead < 0x80) return s[i++];
  const int length = (lead & 0xe0) == 0xc0   ? 2
                     : (lead & 0xf0) == 0xe0 ? 3
                     : (lead & 0xf8) == 0xf0 ? 4
                                             : 0;
  if (length == 0 || i + length > s.size()) return -1;
  long cp = lead & (0x7f >> length);
  for (int k = 1; k < length; ++k) {
    if ((byte(i + k) & 0xc0) != 0x80) return -1;
    cp = cp << 6 | (byte(i + k) & 0x3f);
  }
  i += length;
  constexpr long kShortest[] = {0, 0, 0x80, 0x800, 0x10000};
  return cp >= kShortest[length] && cp <= 0x10ffff && (cp < 0xd800 || cp > 0xdfff) ? cp : -1;
}

// The 66 code points Unicode reserves as noncharacters; yaml-cpp writes each as U+FFFD.
bool is_noncharacter(long c) {
  return (c >= 0xfdd0 && c <= 0xfdef) || (c & 0xfffe) == 0xfffe;
}

// A colour space name must read back from every format brdfnav writes it in: YAML, which holds
// printable Unicode characters only, and the inline spec, which splits items at ',' and trims
// values.
void check_colorspace(std::string_view name) {
  if (name.empty()) throw MaterialError("colorspace: must not be empty");
  if (trim(name) != name)
    throw MaterialError("colorspace: must not start or end with a space or tab");
  for (std::size_t i = 0; i < name.size();) {
    const std::size_t at = i;
    const long c = decode_utf8(name, i);
    if (c < 0x20 || c == 0x7f || (c >= 0x80 && c < 0xa0) || is_noncharacter(c) || c == ',')
      throw MaterialError("colorspace: byte " + std::to_string(at) +
                          " is not allowed (a colour space name is printable UTF-8 without ',')");
  }
}

}  // namespace

Material default_material(ModelId id) {
  Material m;
  m.model = id;
  for (const ParamSpec& p : model_info(id).params) m.params.push_back(p.default_value);
  return m;
}

void validate(const Material& m) {
  const ModelInfo& info = model_info(m.model);
  if (m.params.size() != info.params.size())
    throw MaterialError("params: model '" + std::string(info.name) + "' takes " +
                        std::to_string(info.params.size()) + " parameters, got " +
                        std::to_string(m.params.size()));
  for (std::size_t i = 0; i < info.params.size(); ++i) {
    const ParamSpec& p = info.params[i];
    if (!in_valid_range(p, m.params[i]))
      throw MaterialError("params." + std::string(p.name) + ": " + fmt(m.params[i]) +
                          " is outside the valid range [" + fmt(p.valid_min) + ", " +
                          fmt(p.valid_max) + "]");
  }
  check_rgb(m.rho_d, kRhoDMax, "rho_d");
  check_rgb(m.rho_s, kRhoSMax, "rho_s");
  check_colorspace(m.colorspace);
}

void require_render_colorspace(const Material& m) {
  if (m.colorspace != kDefaultColorspace)
    throw MaterialError("colorspace '" + m.colorspace + "': images and distances are computed in " +
                            std::string(kDefaultColorspace) +
                            " only (give rho_d and rho_s in it; colours are not converted)",
                        ErrorCode::invalid_argument);
}

Closure make_closure(const Material& m) {
  validate(m);
  return Closure(make_lobe(m.model, m.params), m.rho_d, m.rho_s);
}

Material parse_material_spec(std::string_view spec) {
  const std::size_t colon = spec.find(':');
  const std::string_view model_name = trim(spec.substr(0, colon));
  const ModelInfo* info = find_model(model_name);
  if (!info) {
    std::string known;
    for (const ModelInfo& mi : models())
      known += (known.empty() ? "" : ", ") + std::string(mi.name);
    throw MaterialError("unknown model '" + std::string(model_name) + "' (known: " + known + ")");
  }
  Material m = default_material(info->id);
  std::string_view rest = colon == std::string_view::npos ? "" : spec.substr(colon + 1);
  std::vector<std::string_view> seen;
  while (!trim(rest).empty()) {
    const std::size_t comma = rest.find(',');
    const std::string_view item = rest.substr(0, comma);
    rest = comma == std::string_view::npos ? "" : rest.substr(comma + 1);
    const std::size_t eq = item.find('=');
    if (eq == std::string_view::npos)
      throw MaterialError("'" + std::string(trim(item)) + "': expected key=value");
    const std::string_view key = trim(item.substr(0, eq)), value = trim(item.substr(eq + 1));
    if (std::find(seen.begin(), seen.end(), key) != seen.end())
      throw MaterialError("key '" + std::string(key) + "' is given twice");
    seen.push_back(key);
    if (key == "rho_d") {
      m.rho_d = parse_color(value, key);
    } else if (key == "rho_s") {
      m.rho_s = parse_color(value, key);
    } else if (key == "colorspace") {
      m.colorspace = std::string(value);
    } else if (const int i = find_param(*info, key); i >= 0) {
      m.params[i] = parse_number(value, key);
    } else {
      std::string known;
      for (const ParamSpec& p : info->params) known += std::string(p.name) + ", ";
      throw MaterialError("unknown key '" + std::string(key) + "' for model '" +
                          std::string(info->name) + "' (known: " + known +
                          "rho_d, rho_s, colorspace)");
    }
  }
  validate(m);
  return m;
}

std::string format_material_spec(const Material& m) {
  const ModelInfo& info = model_info(m.model);
  std::ostringstream out;
  out << info.name << ':';
  for (std::size_t i = 0; i < info.params.size(); ++i)
    out << info.params[i].name << '=' << fmt(m.params[i]) << ',';
  out << "rho_d=" << fmt(m.rho_d[0]) << '/' << fmt(m.rho_d[1]) << '/' << fmt(m.rho_d[2]);
  out << ",rho_s=" << fmt(m.rho_s[0]) << '/' << fmt(m.rho_s[1]) << '/' << fmt(m.rho_s[2]);
  if (m.colorspace != kDefaultColorspace) out << ",colorspace=" << m.colorspace;
  return out.str();
}

}  // namespace brdfnav
