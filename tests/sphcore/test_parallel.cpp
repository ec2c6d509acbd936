// The particle-loop helpers (sphcore/parallel.hpp) give a serial loop's result
// on one thread and on two, above and below the size where they take threads.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "sphcore/parallel.hpp"

namespace sph {
namespace {

// Values whose largest lie in different threads' shares.
std::vector<double> wave(std::size_t n, double phase) {
  std::vector<double> values(n);
  for (std::size_t i = 0; i < n; ++i) values[i] = std::sin(0.37 * static_cast<double>(i) + phase);
  return values;
}

class OnThreads : public ::testing::TestWithParam<int> {
 protected:
  void SetUp() override {
    before_ = omp_get_max_threads();
    omp_set_num_threads(GetParam());
  }
  void TearDown() override { omp_set_num_threads(before_); }

 private:
  int before_ = 1;
};

TEST_P(OnThreads, ParallelMaxOfEachQuantityIsTheSerialOne) {
  for (const std::size_t n : {std::size_t{7}, std::size_t{10001}}) {
    const std::vector<double> a = wave(n, 0.0), b = wave(n, 1.9);
    const auto [largest_a, largest_b] =
        parallel_max(n, std::array{-5.0, -5.0}, kTeamAtAnySize, [&](long i) {
          return std::array{a[i], -b[i]};
        });
    EXPECT_EQ(largest_a, *std::max_element(a.begin(), a.end())) << "n = " << n;
    EXPECT_EQ(largest_b, -*std::min_element(b.begin(), b.end())) << "n = " << n;
    // `none` stands where no value is larger.
    EXPECT_EQ(parallel_max(n, 2.0, kTeamAtAnySize, [&](long i) { return a[i]; }), 2.0);
    EXPECT_EQ(parallel_max(n, -2.0, [&](long i) { return a[i]; }),
              *std::max_element(a.begin(), a.end()));
  }
}

TEST_P(OnThreads, ParallelFindFirstIsTheSerialScansFind) {
  const std::size_t n = 10001;
  for (const long wanted : {0L, 17L, 5001L, 9000L, 10000L}) {
    // Several hits, in both threads' shares: the first one counts.
    const auto found = [&](long i) { return i == wanted || i == 9500 || i == 10000; };
    EXPECT_EQ(parallel_find_first(n, found), std::min(wanted, 9500L));
  }
  EXPECT_EQ(parallel_find_first(n, [](long) { return false; }), static_cast<long>(n));
}

TEST_P(OnThreads, ParallelAnyIsTheSerialScansAnswer) {
  for (const std::size_t n : {std::size_t{7}, std::size_t{10001}}) {
    const long last = static_cast<long>(n) - 1;
    // One hit at a time, in either thread's share and in the vector loop's remainder.
    for (const long hit : {0L, 3L, last / 2 + 1, last}) {
      const auto found = [&](long i) { return i == hit; };
      EXPECT_TRUE(parallel_any(n, kTeamAtAnySize, found)) << "n = " << n << ", hit " << hit;
    }
    EXPECT_FALSE(parallel_any(n, kTeamAtAnySize, [](long) { return false; })) << "n = " << n;
  }
}

// The neighbour lists keep a store per share: the shares must cover every
// index once, each within its own numbered share.
TEST_P(OnThreads, SharesCoverEveryIndexOnceInNumberedShares) {
  for (const std::size_t n : {std::size_t{0}, std::size_t{7}, std::size_t{10001}}) {
    const long shares = share_count(n, kTeamAtAnySize);
    EXPECT_GE(shares, 1);
    if (GetParam() == 1) {
      EXPECT_EQ(shares, 1);
    }
    std::vector<long> share_of(n, -1);
    std::vector<int> seen(static_cast<std::size_t>(shares), 0);
    for_each_share(n, kTeamAtAnySize, [&](long begin, long end, long share) {
      ASSERT_LT(share, shares);
      ++seen[static_cast<std::size_t>(share)];
      for (long i = begin; i < end; ++i) {
        EXPECT_EQ(share_of[i], -1) << "index " << i << " twice";
        share_of[i] = share;
      }
    });
    EXPECT_EQ(std::count(share_of.begin(), share_of.end(), -1), 0) << "n = " << n;
    for (const int times : seen) EXPECT_LE(times, 1) << "n = " << n;
  }
}

// The neighbour lists keep a store per chunk, and the chunks go to whichever
// thread is free: each chunk must be one contiguous run of indices, numbered
// in index order, and together they must cover every index once.
TEST_P(OnThreads, ChunksAreContiguousNumberedInOrderAndCoverEveryIndexOnce) {
  for (const std::size_t n : {std::size_t{0}, std::size_t{7}, std::size_t{10001}}) {
    const long chunks = chunk_count(n, kTeamAtAnySize);
    EXPECT_GE(chunks, 1);
    if (GetParam() == 1) {
      EXPECT_EQ(chunks, 1);
    } else if (n > 100) {
      EXPECT_GT(chunks, GetParam()) << "one chunk per thread balances nothing";
    }
    std::vector<long> begin_of(static_cast<std::size_t>(chunks), -1),
        end_of(static_cast<std::size_t>(chunks), -1);
    std::vector<int> visits(n, 0);
    for_each_chunk(n, kTeamAtAnySize, [&](long begin, long end, long chunk) {
      ASSERT_GE(chunk, 0);
      ASSERT_LT(chunk, chunks);
      begin_of[static_cast<std::size_t>(chunk)] = begin;
      end_of[static_cast<std::size_t>(chunk)] = end;
      for (long i = begin; i < end; ++i) ++visits[static_cast<std::size_t>(i)];
    });
    EXPECT_EQ(std::count(visits.begin(), visits.end(), 1), static_cast<long>(n)) << "n = " << n;
    for (long c = 0; c < chunks; ++c) {
      EXPECT_EQ(begin_of[static_cast<std::size_t>(c)],
                c == 0 ? 0 : end_of[static_cast<std::size_t>(c - 1)])
          << "chunk " << c << " of " << chunks << ", n = " << n;
    }
  }
}

TEST_P(OnThreads, ParallelPassVisitsEveryIndexOnce) {
  const std::size_t n = 10001;
  std::vector<int> visits(n, 0);
  parallel_pass(n, worth_threads(n), [&](long i) { ++visits[i]; });
  EXPECT_EQ(std::count(visits.begin(), visits.end(), 1), static_cast<long>(n));
}

INSTANTIATE_TEST_SUITE_P(Threads, OnThreads, ::testing::Values(1, 2));

}  // namespace
}  // namespace sph
