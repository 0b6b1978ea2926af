#include "occlusion/core/parallel.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <vector>

namespace occlusion {
namespace {

TEST(Parallel, VisitsEveryIndexExactlyOnce) {
  for (const unsigned threads : {1u, 2u, 4u, 0u}) {
    std::vector<std::atomic<int>> visits(10007);
    parallel_for(visits.size(), 64, threads, [&](std::size_t b, std::size_t e) {
      for (std::size_t i = b; i < e; ++i) ++visits[i];
    });
    for (const auto& v : visits) ASSERT_EQ(v.load(), 1);
  }
}

TEST(Parallel, EmptyRangeCallsNothing) {
  bool called = false;
  parallel_for(0, 8, 2, [&](std::size_t, std::size_t) { called = true; });
  EXPECT_FALSE(called);
}

TEST(Parallel, RethrowsTheWorkersException) {
  EXPECT_THROW(parallel_for(1000, 10, 2,
                            [](std::size_t b, std::size_t) {
                              if (b >= 500) throw std::runtime_error("boom");
                            }),
               std::runtime_error);
}

TEST(Parallel, ResolvesZeroToAtLeastOneThread) {
  EXPECT_GE(resolve_thread_count(0), 1u);
  EXPECT_EQ(resolve_thread_count(3), 3u);
}

}  // namespace
}  // namespace occlusion
