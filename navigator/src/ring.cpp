#include "ring.h"

#include <brdfnav/core/cielab.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

namespace brdfnav::nav {

namespace {

// The colour tabs' "ab+<degrees>" directions in words: each word with a colour it names (sRGB as
// a colour picker gives it). CIELAB's hue angle is not the colour wheel's: +a* (0 degrees) looks
// pink, red sits at 40, green at 136, and the blues crowd between 250 and 310.
constexpr std::array<HueWord, 8> kHueWords{{{"towards pink", {1.0, 0.4, 0.7}},
                                            {"towards red", {1.0, 0.0, 0.0}},
                                            {"towards gold", {1.0, 0.84, 0.0}},
                                            {"towards green", {0.0, 0.8, 0.0}},
                                            {"towards teal", {0.0, 0.5, 0.5}},
                                            {"towards cerulean", {0.0, 0.6, 0.8}},
                                            {"towards blue", {0.0, 0.5, 1.0}},
                                            {"towards violet", {0.5, 0.0, 1.0}}}};

// The smallest angle between two hue angles, in degrees.
double hue_gap(double a, double b) {
  const double d = std::fmod(std::abs(a - b), 360.0);
  return std::min(d, 360 - d);
}

std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", v);
  return text;
}

std::string rgb(const Rgb& c) {
  return number(c[0]) + " " + number(c[1]) + " " + number(c[2]);
}

bool differ(double a, double b) {
  return std::abs(a - b) > 1e-12 * std::max(std::abs(a), std::abs(b));
}

std::string lobe_words(const Neighbor& n) {
  const std::string& label = n.label;
  const bool up = label.back() == '+';
  const std::string name = label.substr(0, label.size() - 1);
  for (const ParamSpec& spec : model_info(n.material.model).params)
    if (spec.name == name) return std::string(up ? spec.more : spec.less);
  // Ward's "alpha+" / "alpha-": both slopes by one factor.
  return up ? "rougher" : "sharper";
}

std::string color_words(const Neighbor& n) {
  if (n.label == "L+") return "lighter";
  if (n.label == "L-") return "darker";
  if (n.label.rfind("ab+", 0) == 0) return hue_word(std::stoi(n.label.substr(3)));
  return n.label;
}

}  // namespace

double hue_angle(const HueWord& word) {
  const auto decode = [](double c) {  // the sRGB transfer function, to linear
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
  };
  const Vec3 lab =
      lab_from_rec709(Rgb(decode(word.srgb[0]), decode(word.srgb[1]), decode(word.srgb[2])));
  const double degrees = std::atan2(lab[2], lab[1]) * 180 / kPi;
  return degrees < 0 ? degrees + 360 : degrees;
}

std::span<const HueWord> hue_words() {
  return kHueWords;
}

std::string hue_word(double degrees) {
  // The words' hue angles, computed once: every colour offer asks.
  static const std::array<double, kHueWords.size()> angles = [] {
    std::array<double, kHueWords.size()> a{};
    for (std::size_t i = 0; i < a.size(); ++i) a[i] = hue_angle(kHueWords[i]);
    return a;
  }();
  std::size_t nearest = 0;
  for (std::size_t i = 1; i < angles.size(); ++i)
    if (hue_gap(angles[i], degrees) < hue_gap(angles[nearest], degrees)) nearest = i;
  return kHueWords[nearest].words;
}

namespace {

std::string words(const Neighbor& n) {
  switch (n.tab) {
    case Tab::lobe:
      return lobe_words(n);
    case Tab::diffuse:
    case Tab::specular:
      return color_words(n);
    case Tab::models:
      return "as " + std::string(model_info(n.material.model).title);
    case Tab::gallery:
      return std::string(model_info(n.material.model).title);
  }
  return n.label;
}

// "alpha_x 0.1 -> 0.0707, rho_s 0.5 0.5 0.5 -> ..." for what differs; a material of another
// model is given whole ("he: sigma 0.5, tau 8, eta 1.5; rho_s ...").
std::string change(const Material& from, const Material& to) {
  const ModelInfo& info = model_info(to.model);
  std::string out;
  const auto add = [&](const std::string& item) { out += (out.empty() ? "" : ", ") + item; };
  if (from.model != to.model) {
    std::string params;
    for (std::size_t i = 0; i < info.params.size(); ++i)
      params += (i ? ", " : "") + std::string(info.params[i].name) + " " + number(to.params[i]);
    return std::string(info.name) + ": " + params + "; rho_d " + rgb(to.rho_d) + ", rho_s " +
           rgb(to.rho_s);
  }
  for (std::size_t i = 0; i < info.params.size(); ++i)
    if (differ(from.params[i], to.params[i]))
      add(std::string(info.params[i].name) + " " + number(from.params[i]) + " -> " +
          number(to.params[i]));
  for (int c = 0; c < 3; ++c) {
    if (differ(from.rho_d[c], to.rho_d[c])) {
      add("rho_d " + rgb(from.rho_d) + " -> " + rgb(to.rho_d));
      break;
    }
  }
  for (int c = 0; c < 3; ++c) {
    if (differ(from.rho_s[c], to.rho_s[c])) {
      add("rho_s " + rgb(from.rho_s) + " -> " + rgb(to.rho_s));
      break;
    }
  }
  return out.empty() ? "no change" : out;
}

}  // namespace

std::string opposite_label(const std::string& label) {
  if (label.rfind("ab+", 0) == 0)
    return "ab+" + std::to_string((std::stoi(label.substr(3)) + 180) % 360);
  if (label.empty() || (label.back() != '+' && label.back() != '-')) return "";
  return label.substr(0, label.size() - 1) + (label.back() == '+' ? '-' : '+');
}

std::vector<Neighbor> ring_order(std::vector<Neighbor> offers) {
  std::vector<Neighbor> first, second, single;
  std::vector<bool> placed(offers.size(), false);
  for (std::size_t i = 0; i < offers.size(); ++i) {
    if (placed[i]) continue;
    placed[i] = true;
    const std::string other = opposite_label(offers[i].label);
    std::size_t j = 0;
    while (j < offers.size() && (placed[j] || other.empty() || offers[j].label != other)) ++j;
    if (j == offers.size()) {
      single.push_back(std::move(offers[i]));
      continue;
    }
    placed[j] = true;
    first.push_back(std::move(offers[i]));
    second.push_back(std::move(offers[j]));
  }
  const int pairs = static_cast<int>(first.size());
  for (int i = 0; i < pairs; ++i) first[i].opposite = pairs + i, second[i].opposite = i;
  for (Neighbor& n : single) n.opposite = -1;
  first.insert(first.end(), std::make_move_iterator(second.begin()),
               std::make_move_iterator(second.end()));
  first.insert(first.end(), std::make_move_iterator(single.begin()),
               std::make_move_iterator(single.end()));
  return first;
}

void describe(std::vector<Neighbor>& offers, const Material& current) {
  for (Neighbor& n : offers) {
    n.words = words(n);
    n.change = change(current, n.material);
  }
}

}  // namespace brdfnav::nav
