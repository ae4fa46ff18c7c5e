// The database the database targets damage: tests/fuzz/database, made by
// `brdfnav precompute --profile test --res 8` in format version 1 and converted to version 2 (its
// embedding tables transposed to one row per column, the manifest's version and checksums
// updated), so that the table target reaches the mapped reader. Regenerate or convert it when the
// format version changes; corpus_replay.cpp checks that it still opens. Each process works on a
// copy.
#pragma once

#include "fuzz_target.h"

#include <brdfnav/navigator/database.h>

namespace brdfnav::fuzz {

// A copy of the fixture in the scratch directory, made on the first call.
inline const std::filesystem::path& database_copy() {
  static const std::filesystem::path dir = [] {
    const std::filesystem::path copy = scratch_dir() / "db";
    std::filesystem::copy(BRDFNAV_FUZZ_DATABASE, copy, std::filesystem::copy_options::recursive);
    return copy;
  }();
  return dir;
}

// The fixture's manifest, as made.
inline const std::string& fixture_manifest() {
  static const std::string text =
      read_file(std::filesystem::path(BRDFNAV_FUZZ_DATABASE) / "manifest.yaml");
  return text;
}

}  // namespace brdfnav::fuzz
