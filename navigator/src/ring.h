// What a tab's offers say beyond their materials: their order on the ring, each one's opposite,
// and their words for an artist. The one definition the CLI's sheets and the page draw from.
#pragma once

#include <brdfnav/navigator/navigator.h>

#include <string>
#include <vector>

namespace brdfnav::nav {

// The label of the opposite direction ("x+" <-> "x-", "ab+<a>" <-> "ab+<a + 180>"), or "" for a
// label without one (models, gallery).
std::string opposite_label(const std::string& label);

// Orders `offers` for the ring: one of each opposite pair, then their partners in the same order,
// then the offers without a partner; sets each offer's `opposite`.
std::vector<Neighbor> ring_order(std::vector<Neighbor> offers);

// Sets each offer's `words` and `change` from its tab, label and material against `current`.
void describe(std::vector<Neighbor>& offers, const Material& current);

}  // namespace brdfnav::nav
