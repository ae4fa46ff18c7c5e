// A database's embedding is mapped, not read (format 2, docs/DATABASE.md): what the process holds
// of it is what its queries touched, read here from /proc/self/smaps for the mapping itself.
#include "navigator/navigator_fixture.h"

#include <brdfnav/navigator/navigator.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>

namespace brdfnav {
namespace {

// The resident kB of the mapping that holds `address`, or -1 when no mapping holds it.
long resident_kb_of_mapping(const void* address) {
  const auto at = reinterpret_cast<std::uintptr_t>(address);
  std::ifstream smaps("/proc/self/smaps");
  bool inside = false;
  for (std::string line; std::getline(smaps, line);) {
    std::uintptr_t begin = 0, end = 0;
    char dash = 0;
    std::istringstream fields(line);
    if (fields >> std::hex >> begin >> dash >> end && dash == '-') {
      inside = begin <= at && at < end;
    } else if (inside && line.rfind("Rss:", 0) == 0) {
      return std::stol(line.substr(4));
    }
  }
  return -1;
}

// Opening walks every node for the gallery and gives the pages back; a query maps what it reads.
TEST(EmbeddingPages, OpeningHoldsNoneAndAQueryOnlyWhatItRead) {
  const Navigator navigator = Navigator::open(test::NavigationDatabase::get().dir());
  const ModelEmbedding& ward = *navigator.database().embedding(ModelId::ward);
  const float* coefficients = ward.coefficients().data();
  EXPECT_EQ(resident_kb_of_mapping(coefficients), 0);
  Material m = default_material(ModelId::ward);
  m.params = {0.05, 0.1};
  navigator.neighbors(m, 0.03, Tab::lobe);
  EXPECT_GT(resident_kb_of_mapping(coefficients), 0);
  ward.release_pages();
  EXPECT_EQ(resident_kb_of_mapping(coefficients), 0);
}

}  // namespace
}  // namespace brdfnav
