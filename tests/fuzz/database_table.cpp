// Fuzz target: a float32 table of a database (the reader behind Database::open). The input
// replaces embedding/ward.f32 of a copy of the fixture, and the manifest gets the input's SHA-1,
// so that the input gets past verification to the table's header and shape checks.
// Rejections are DatabaseError.
#include "fixture_database.h"

namespace {

constexpr const char* kTable = "embedding/ward.f32";

std::string with_checksum(const std::string& manifest, const std::string& old_sha,
                          const std::string& new_sha) {
  std::string text = manifest;
  const std::size_t at = text.find(old_sha);
  if (at == std::string::npos) brdfnav::fuzz::fail(std::string("the fixture lists no ") + kTable);
  return text.replace(at, old_sha.size(), new_sha);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace brdfnav;
  const std::filesystem::path& dir = fuzz::database_copy();
  static const std::string fixture_sha =
      file_sha1(std::filesystem::path(BRDFNAV_FUZZ_DATABASE) / kTable);
  fuzz::write_file(dir / kTable, fuzz::as_text(data, size));
  fuzz::write_file(dir / "manifest.yaml",
                   with_checksum(fuzz::fixture_manifest(), fixture_sha, file_sha1(dir / kTable)));
  try {
    Database::open(dir);
  } catch (const DatabaseError&) {
  }
  return 0;
}
