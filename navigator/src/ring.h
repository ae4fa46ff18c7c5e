// What a tab's offers say beyond their materials: their order on the ring, each one's opposite,
// and their words for an artist. The one definition the CLI's sheets and the page draw from.
#pragma once

#include <brdfnav/navigator/navigator.h>

#include <array>
#include <span>
#include <string>
#include <vector>

namespace brdfnav::nav {

// The label of the opposite direction ("x+" <-> "x-", "ab+<a>" <-> "ab+<a + 180>"), or "" for a
// label without one (models, gallery).
std::string opposite_label(const std::string& label);

// Orders `offers` for the ring: one of each opposite pair, then their partners in the same order,
// then the offers without a partner; sets each offer's `opposite`.
std::vector<Neighbor> ring_order(std::vector<Neighbor> offers);

// A word for a hue, with a colour it names: sRGB, display-encoded, as a colour picker gives it.
struct HueWord {
  const char* words;
  std::array<double, 3> srgb;
};
// Every hue word, and the CIELAB hue angle (degrees, [0, 360)) of its colour.
std::span<const HueWord> hue_words();
double hue_angle(const HueWord& word);
// The words of the CIELAB hue direction `degrees`: those of the hue word whose colour's hue is
// nearest. What the colour tabs' "ab+<degrees>" offers say.
std::string hue_word(double degrees);

// Sets each offer's `words` and `change` from its tab, label and material against `current`.
void describe(std::vector<Neighbor>& offers, const Material& current);

}  // namespace brdfnav::nav
