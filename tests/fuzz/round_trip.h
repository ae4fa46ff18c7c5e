// The material targets' oracle beyond "no crash": a material that was read writes back, as YAML
// (brdfnav export, write_material_yaml) and as an inline spec, to text that reads back as the same
// material, bit for bit.
#pragma once

#include "fuzz_target.h"

#include <brdfnav/io/material_yaml.h>

namespace brdfnav::fuzz {

inline bool same(const Material& a, const Material& b) {
  return a.model == b.model && a.params == b.params && (a.rho_d == b.rho_d).all() &&
         (a.rho_s == b.rho_s).all() && a.colorspace == b.colorspace;
}

inline void check_round_trips(const Material& m) {
  const std::string yaml = material_to_yaml(m);
  if (!same(parse_material_yaml(yaml, "<round trip>"), m))
    fail("the YAML round trip changes the material:\n" + yaml);
  const std::string spec = format_material_spec(m);
  if (!same(parse_material_spec(spec), m))
    fail("the inline spec round trip changes the material: " + spec);
}

}  // namespace brdfnav::fuzz
