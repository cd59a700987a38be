// Seeded randomness (common/util/random.hpp): the counter-based stream draws the same
// numbers wherever it is drawn, covers [0, 1) evenly, and its keys keep streams apart.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <vector>

#include "common/util/random.hpp"

namespace plumbago {
namespace {

TEST(CounterStream, TheSameKeyDrawsTheSameNumbersAndNeighbouringKeysOthers) {
  CounterStream a(stream_key({1, 7, 0})), b(stream_key({1, 7, 0})), c(stream_key({1, 7, 1})), d(stream_key({1, 8, 0}));
  size_t same_c = 0, same_d = 0;
  for (int k = 0; k < 1000; ++k) {
    double x = a.uniform();
    EXPECT_EQ(x, b.uniform());
    same_c += x == c.uniform(), same_d += x == d.uniform();
  }
  EXPECT_LE(same_c + same_d, 2u);  // 24-bit numbers: a coincidence in 2000 draws is rare
}

TEST(CounterStream, DrawsEvenlyInTheUnitInterval) {
  std::vector<int> bins(16, 0);
  const int n = 160000;
  for (uint32_t key = 0; key < 16; ++key) {
    CounterStream s(stream_key({key}));
    for (int k = 0; k < n / 16; ++k) {
      double x = s.uniform();
      ASSERT_GE(x, 0.0);
      ASSERT_LT(x, 1.0);
      ++bins[size_t(x * 16)];
    }
  }
  // Each bin holds n / 16 = 10000 in expectation, standard deviation about 97.
  for (int b : bins) EXPECT_NEAR(b, n / 16, 500) << "a sixteenth of [0, 1)";
}

TEST(CounterStream, TheHashIsABijectionOnTheInputsItIsGiven) {
  std::set<uint32_t> out;
  for (uint32_t x = 0; x < 200000; ++x) out.insert(hash32(x));
  EXPECT_EQ(out.size(), 200000u);
  EXPECT_NE(hash32(1), 1u);  // not the identity
}

}  // namespace
}  // namespace plumbago
