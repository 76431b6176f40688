/// The subdomain loop (common/parallel.hpp): every index once, exceptions reach the caller,
/// nested loops run serially, and the pool follows set_threads.

#include "common/error.hpp"
#include "common/parallel.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <set>
#include <thread>
#include <vector>

using namespace feticon;

namespace
{
/// set_threads for the test's duration (OMP_NUM_THREADS would override it: cleared).
struct Threads
{
  explicit Threads(int n)
  {
    unsetenv("OMP_NUM_THREADS");
    set_threads(n);
  }
  ~Threads() { set_threads(hardware_cores()); }
};
} // namespace

TEST(ParallelFor, VisitsEveryIndexOnceOnSeveralThreads)
{
  const Threads threads(3);
  EXPECT_EQ(feticon::threads(), 3);
  std::vector<std::atomic<int>> visits(1000);
  std::set<std::thread::id> ids;
  std::mutex mutex;
  for (int repeat = 0; repeat < 50; ++repeat) // the pool is reused loop after loop
    parallel_for(0, 1000, min_parallel_work, [&](int32_t i) {
      ++visits[i];
      std::lock_guard lock(mutex);
      ids.insert(std::this_thread::get_id());
    });
  for (const auto& v : visits)
    EXPECT_EQ(v.load(), 50);
  EXPECT_GE(ids.size(), 2u); // work did leave the calling thread
  parallel_for(5, 5, min_parallel_work, [&](int32_t) { FAIL() << "empty range"; });
}

TEST(ParallelFor, RethrowsTheErrorOfAnIterationAfterTheLoop)
{
  const Threads threads(2);
  std::atomic<int> done = 0;
  EXPECT_THROW(parallel_for(
                   0, 100, min_parallel_work,
                   [&](int32_t i) {
    if (i == 37)
      FETICON_CHECK(false, "subdomain 37 is not positive definite");
    ++done;
                   }),
               Error);
  EXPECT_EQ(done.load(), 99); // the other iterations still ran
  // and the pool still works afterwards
  std::atomic<int> count = 0;
  parallel_for(0, 10, min_parallel_work, [&](int32_t) { ++count; });
  EXPECT_EQ(count.load(), 10);
}

// Several iterations throw: the caller gets the smallest index's error every time, as a serial
// loop would give it, not whichever thread was first (an inverted element's message named a
// different element from run to run).
TEST(ParallelFor, RethrowsTheSmallestThrowingIndexWhateverTheTiming)
{
  const Threads threads(2);
  for (int repeat = 0; repeat < 1000; ++repeat) // without the rule: a wrong message within a few hundred
  {
    std::string message;
    try
    {
      parallel_for(0, 64, min_parallel_work, [&](int32_t i) {
        if (i % 16 == 5) // 5, 21, 37, 53
          FETICON_CHECK(false, "iteration " << i);
      });
    }
    catch (const Error& e)
    {
      message = e.what();
    }
    ASSERT_EQ(message, "iteration 5") << "repeat " << repeat;
  }
}

TEST(ParallelFor, NestedLoopsRunSeriallyInTheirIteration)
{
  const Threads threads(2);
  std::vector<int> sums(8, 0);
  parallel_for(0, 8, min_parallel_work, [&](int32_t i) {
    const std::thread::id outer = std::this_thread::get_id();
    parallel_for(0, 10, min_parallel_work, [&](int32_t j) {
      EXPECT_EQ(std::this_thread::get_id(), outer);
      sums[i] += j;
    });
  });
  for (int s : sums)
    EXPECT_EQ(s, 45);
}

TEST(ParallelFor, SmallWorkRunsInTheCaller)
{
  const Threads threads(2);
  const std::thread::id caller = std::this_thread::get_id();
  parallel_for(0, 20, min_parallel_work - 1, [&](int32_t) { EXPECT_EQ(std::this_thread::get_id(), caller); });
}

TEST(ParallelFor, OneThreadRunsInTheCaller)
{
  const Threads threads(1);
  const std::thread::id caller = std::this_thread::get_id();
  parallel_for(0, 20, min_parallel_work, [&](int32_t) { EXPECT_EQ(std::this_thread::get_id(), caller); });
}
