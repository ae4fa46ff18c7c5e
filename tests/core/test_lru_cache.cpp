// LruCache (core/lru_cache.h): what the thumbnails', the exact renders' and the server's rings'
// caches share. The least recently used goes first, within the budget; the newest always stays.
#include <brdfnav/core/lru_cache.h>
#include <gtest/gtest.h>

#include <string>

namespace brdfnav {
namespace {

TEST(LruCache, DropsTheLeastRecentlyUsedOverTheBudget) {
  LruCache<std::string, int> cache(10);
  cache.insert("a", 1, 4);
  cache.insert("b", 2, 4);
  ASSERT_NE(cache.find("a"), nullptr);  // a is now the most recently used
  cache.insert("c", 3, 4);              // 12 > 10: b, the least recently used, goes
  EXPECT_EQ(cache.peek("b"), nullptr);
  ASSERT_NE(cache.peek("a"), nullptr);
  EXPECT_EQ(*cache.peek("a"), 1);
  EXPECT_EQ(*cache.peek("c"), 3);
  EXPECT_EQ(cache.size(), 2u);
  EXPECT_EQ(cache.total(), 8u);
}

TEST(LruCache, PeekIsNotAUse) {
  LruCache<int, int> cache(2);
  cache.insert(1, 10, 1);
  cache.insert(2, 20, 1);
  EXPECT_EQ(*cache.peek(1), 10);  // 1 stays the least recently used
  cache.insert(3, 30, 1);
  EXPECT_EQ(cache.peek(1), nullptr);
  EXPECT_NE(cache.peek(2), nullptr);
}

TEST(LruCache, AKeyHeldKeepsItsValueAndCost) {
  LruCache<int, int> cache(100);
  int& first = cache.insert(1, 10, 7);
  int& again = cache.insert(1, 99, 50);
  EXPECT_EQ(&first, &again);
  EXPECT_EQ(again, 10);
  EXPECT_EQ(cache.total(), 7u);
  // A value found can be changed in place (the server's latest ring of a page).
  *cache.find(1) = 11;
  EXPECT_EQ(*cache.peek(1), 11);
}

TEST(LruCache, TheNewestStaysEvenOverTheBudget) {
  LruCache<int, int> cache(5);
  cache.insert(1, 1, 3);
  cache.insert(2, 2, 8);  // alone over the budget: everything else goes, it stays
  EXPECT_EQ(cache.size(), 1u);
  EXPECT_NE(cache.peek(2), nullptr);
  EXPECT_EQ(cache.total(), 8u);
  cache.insert(3, 3, 1);  // 9 > 5: 2 goes
  EXPECT_EQ(cache.size(), 1u);
  EXPECT_EQ(cache.total(), 1u);
}

}  // namespace
}  // namespace brdfnav
