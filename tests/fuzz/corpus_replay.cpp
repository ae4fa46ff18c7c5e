// Replays every file of tests/corpus/<target>/ (the seeds, and the crashes `./run fuzz` found once
// they are fixed) through the target's entry point, so that CI keeps them fixed without clang.
#include "fuzz_target.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#ifdef BRDFNAV_FUZZ_DATABASE_TARGET
#include "fixture_database.h"
#endif

namespace brdfnav::fuzz {
namespace {

namespace fs = std::filesystem;

TEST(FuzzCorpus, EveryInputIsHandled) {
  std::vector<fs::path> inputs;
  for (const auto& e : fs::recursive_directory_iterator(BRDFNAV_FUZZ_CORPUS))
    if (e.is_regular_file()) inputs.push_back(e.path());
  std::sort(inputs.begin(), inputs.end());
  ASSERT_FALSE(inputs.empty()) << "no corpus in " << BRDFNAV_FUZZ_CORPUS;
  for (const fs::path& input : inputs) {
    SCOPED_TRACE(input.string());
    std::fprintf(stderr, "replaying %s\n", input.c_str());  // names the input should it abort
    const std::string bytes = read_file(input);
    EXPECT_NO_THROW(
        LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()));
  }
}

#ifdef BRDFNAV_FUZZ_DATABASE_TARGET
// The fuzzers only get deep while the fixture is a database this build opens: after a format
// change, regenerate tests/fuzz/database (fixture_database.h) and its corpus seeds.
TEST(FuzzCorpus, TheFixtureDatabaseOpens) {
  EXPECT_NO_THROW(Database::open(BRDFNAV_FUZZ_DATABASE));
}
#endif

}  // namespace
}  // namespace brdfnav::fuzz
