// SmallVector against std::vector: the same seeded sequence of operations on both, with elements that
// own memory (std::string), so that a lost destructor, a double free or a stale inline pointer shows up
// under the sanitizer build; and the inline room is really used before the heap.
#include "core/small_vector.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "tests/support/seeded_rng.hpp"

namespace hlr {
namespace {

template <typename Small>
void expect_same(const Small& s, const std::vector<std::string>& v, int step) {
  ASSERT_EQ(s.size(), v.size()) << "step " << step;
  for (std::size_t i = 0; i < v.size(); ++i) ASSERT_EQ(s[i], v[i]) << "step " << step << " index " << i;
}

TEST(SmallVector, BehavesAsStdVectorUnderSeededOperations) {
  test::Rng rng(7);
  SmallVector<std::string, 3> s;
  std::vector<std::string> v;
  for (int step = 0; step < 20000; ++step) {
    // Long strings own heap memory; short ones live in the string itself.
    const std::string item = std::to_string(step) + (step % 3 == 0 ? std::string(40, 'x') : "");
    switch (rng.integer(0, 11)) {
      case 0:
      case 1:
      case 2:
        s.push_back(item);
        v.push_back(item);
        break;
      case 3:
        if (!v.empty()) s.pop_back(), v.pop_back();
        break;
      case 4: {
        const auto n = static_cast<std::size_t>(rng.integer(0, 8));
        s.resize(n, item);
        v.resize(n, item);
        break;
      }
      case 5: {
        const auto at = static_cast<std::ptrdiff_t>(rng.integer(0, static_cast<int>(v.size())));
        const std::vector<std::string> more{item, item + "a"};
        s.insert(s.begin() + at, more.begin(), more.end());
        v.insert(v.begin() + at, more.begin(), more.end());
        break;
      }
      case 6:
        if (!v.empty()) {
          const auto at = static_cast<std::ptrdiff_t>(rng.integer(0, static_cast<int>(v.size()) - 1));
          s.erase(s.begin() + at);
          v.erase(v.begin() + at);
        }
        break;
      case 7: {  // copy out and back
        SmallVector<std::string, 3> copy = s;
        s = copy;
        break;
      }
      case 8: {  // move out and back
        SmallVector<std::string, 3> moved = std::move(s);
        EXPECT_TRUE(s.empty());  // NOLINT: moved-from is empty by contract
        s = std::move(moved);
        break;
      }
      case 9:
        if (!v.empty()) {
          s.push_back(s.front());  // an element of itself, at capacity or not
          v.push_back(v.front());
        }
        break;
      case 10:
        if (rng.integer(0, 9) == 0) s.clear(), v.clear();
        break;
      default:
        s.assign(v.begin(), v.end());
        break;
    }
    expect_same(s, v, step);
    if (::testing::Test::HasFatalFailure()) return;
  }
}

TEST(SmallVector, KeepsSmallContentsInline) {
  SmallVector<std::uint32_t, 4> s{1, 2, 3, 4};
  const auto* inside = reinterpret_cast<const unsigned char*>(&s);
  const auto* data = reinterpret_cast<const unsigned char*>(s.data());
  EXPECT_TRUE(data >= inside && data < inside + sizeof s);  // no heap for four
  s.push_back(5);
  data = reinterpret_cast<const unsigned char*>(s.data());
  EXPECT_FALSE(data >= inside && data < inside + sizeof s);  // the fifth goes to the heap
  EXPECT_EQ(s, (std::vector<std::uint32_t>{1, 2, 3, 4, 5}));
  SmallVector<std::uint32_t, 4> moved = std::move(s);  // a heap block is handed over, not copied
  EXPECT_EQ(reinterpret_cast<const unsigned char*>(moved.data()), data);
}

}  // namespace
}  // namespace hlr
