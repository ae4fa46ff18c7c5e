// Fuzz target: an inline material spec `model:key=value,...` (what `--material` reads when it is
// not a file). Rejections are MaterialError; what is accepted round-trips.
#include "round_trip.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace brdfnav;
  Material m;
  try {
    m = parse_material_spec(fuzz::as_text(data, size));
  } catch (const MaterialError&) {
    return 0;
  }
  fuzz::check_round_trips(m);
  return 0;
}
