// A database's embedding is mapped, not read (format 2, docs/DATABASE.md): what the process holds
// of it is what its queries touched, read here from /proc/self/smaps for the mapping itself.
#include "navigator/navigator_fixture.h"

#include <brdfnav/navigator/navigator.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

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

// What a server does when idle (serve's IdleRelease): every model's pages go back, and the next
// query reads them again to the same answer.
TEST(EmbeddingPages, TheNavigatorGivesBackEveryModelsPagesAndAnswersAsBefore) {
  const Navigator navigator = Navigator::open(test::NavigationDatabase::get().dir());
  Material m = default_material(ModelId::ward);
  m.params = {0.05, 0.1};
  const std::vector<Neighbor> before = navigator.neighbors(m, 0.03, Tab::models);
  std::vector<const float*> mapped;
  for (const ProfileGrid& g : navigator.database().manifest().grids)
    mapped.push_back(navigator.database().embedding(g.model)->coefficients().data());
  long held = 0;
  for (const float* p : mapped) held += resident_kb_of_mapping(p);
  EXPECT_GT(held, 0) << "the models tab read no other model's pages";
  navigator.release_pages();
  for (const float* p : mapped) EXPECT_EQ(resident_kb_of_mapping(p), 0);
  const std::vector<Neighbor> after = navigator.neighbors(m, 0.03, Tab::models);
  ASSERT_EQ(after.size(), before.size());
  for (std::size_t i = 0; i < after.size(); ++i) {
    EXPECT_EQ(after[i].material.params, before[i].material.params) << i;
    EXPECT_EQ(after[i].distance, before[i].distance) << i;
  }
}

}  // namespace
}  // namespace brdfnav
