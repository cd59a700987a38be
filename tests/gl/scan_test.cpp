// Exclusive prefix sums on the GPU (gpu/gl/scan.hpp) against std::exclusive_scan, across the
// sizes where its steps change: one partial tile and one whole tile (one dispatch), whole
// tiles, and more tiles than the one-workgroup step has invocations (each then sums a run of
// them); and with the count left on the GPU, under a bound of one tile and of many.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>
#include <utility>
#include <vector>

#include "gpu/gl/scan.hpp"
#include "tests/support/test_scenes.hpp"

namespace plumbago::gpu {
namespace {

class Scan : public testing::GlTest {};

TEST_F(Scan, GivesTheSumsBeforeEachValueAndTheTotalAfterThem) {
  ExclusiveScan scan;
  std::mt19937 random(7);
  for (size_t n :
       {size_t(1), size_t(5), size_t(2047), size_t(2048), size_t(2049), size_t(300'000), size_t(1'100'000)}) {
    SCOPED_TRACE(n);
    std::vector<uint32_t> values(n + 1, 0);
    for (size_t k = 0; k < n; ++k) values[k] = random() % 4;  // zeros and runs, as marks and counts are
    std::vector<uint32_t> expected(n + 1);
    std::exclusive_scan(values.begin(), values.end(), expected.begin(), 0u);
    Buffer buffer = make_buffer(values.data(), values.size() * sizeof(uint32_t));
    scan(buffer, n + 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    std::vector<uint32_t> got(n + 1);
    read_buffer(buffer, got.data(), got.size() * sizeof(uint32_t));
    EXPECT_EQ(got, expected);
  }
}

// The count read on the GPU, scaled: the total's slot (1 here) becomes the total whatever it
// held, what lies past it (9) stays; a count over the capacity is cut to it.
TEST_F(Scan, ScansTheCountTheGpuHolds) {
  ExclusiveScan scan;
  std::mt19937 random(11);
  const std::pair<size_t, std::vector<uint32_t>> cases[] = {{2048, {0u, 1u, 1023u, 1024u, 5000u}},
                                                            {700'001, {0u, 1u, 1024u, 1025u, 350'000u, 400'000u}}};
  for (const auto& [capacity, counts_held] : cases)
    for (uint32_t count : counts_held) {
      SCOPED_TRACE(::testing::Message() << "capacity " << capacity << ", count " << count);
      const size_t n = std::min<size_t>(2 * size_t(count), capacity - 1);
      std::vector<uint32_t> values(capacity, 9);
      for (size_t k = 0; k < n; ++k) values[k] = random() % 4;
      values[n] = 1;
      std::vector<uint32_t> expected = values;
      std::exclusive_scan(expected.begin(), expected.begin() + std::ptrdiff_t(n) + 1, expected.begin(), 0u);
      const uint32_t counts[3] = {5, count, 6};
      Buffer buffer = make_buffer(values.data(), values.size() * sizeof(uint32_t));
      Buffer held = make_buffer(counts, sizeof counts);
      scan(buffer, capacity, held, 1, 2);
      glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
      std::vector<uint32_t> got(capacity);
      read_buffer(buffer, got.data(), got.size() * sizeof(uint32_t));
      EXPECT_EQ(got, expected);
    }
}

}  // namespace
}  // namespace plumbago::gpu
