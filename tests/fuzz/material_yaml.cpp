// Fuzz target: a material YAML document (what `--material FILE` and the C ABI's YAML loader
// read, through material_from_node). Rejections are MaterialError; what is accepted round-trips.
#include "round_trip.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace brdfnav;
  Material m;
  try {
    m = parse_material_yaml(fuzz::as_text(data, size), "fuzz.yaml");
  } catch (const MaterialError&) {
    return 0;
  }
  fuzz::check_round_trips(m);
  return 0;
}
