// Fuzz target: a database manifest (Database::open on a copy of the fixture database whose
// manifest.yaml is the input). Rejections are DatabaseError.
#include "fixture_database.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace brdfnav;
  const std::filesystem::path& dir = fuzz::database_copy();
  fuzz::write_file(dir / "manifest.yaml", fuzz::as_text(data, size));
  try {
    Database::open(dir);
  } catch (const DatabaseError&) {
  }
  return 0;
}
