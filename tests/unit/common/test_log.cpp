/// log::warning keeps its lines for take_warnings() (common/log.hpp), which run summaries list.
/// Reference: the definition: each line once, in the order first logged, a repeated one with
/// its count and the contexts of its first and last occurrence, then cleared.

#include "common/log.hpp"

#include <gtest/gtest.h>

#include <iostream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

using namespace feticon;

namespace
{
/// stderr and the log level of one test: warnings printed into `text`, both restored at the end.
struct CapturedWarnings
{
  CapturedWarnings() : level(log::level()), saved(std::cerr.rdbuf(text.rdbuf()))
  {
    log::take_warnings(); // whatever earlier tests logged
    log::set_level(log::Level::warning);
  }
  ~CapturedWarnings()
  {
    std::cerr.rdbuf(saved);
    log::set_level(level);
    log::set_context("");
  }
  CapturedWarnings(const CapturedWarnings&) = delete;
  CapturedWarnings& operator=(const CapturedWarnings&) = delete;
  std::ostringstream text;
  log::Level level;
  std::streambuf* saved;
};
} // namespace

TEST(Log, WarningsAreKeptOnceUntilTaken)
{
  log::take_warnings(); // whatever earlier tests logged
  const log::Level level = log::level();
  log::set_level(log::Level::quiet); // kept even when not printed
  log::set_context("");
  log::warning("first");
  log::warning("second");
  log::set_context("load step 2, outer iteration 5");
  log::warning("first");
  log::set_level(level);
  EXPECT_EQ(
      log::take_warnings(),
      (std::vector<std::string>{"first (2 times, first at set-up, last at load step 2, outer iteration 5)", "second"}));
  EXPECT_TRUE(log::take_warnings().empty());
  log::set_context("");
}

// A warning met at every outer iteration (fricloop: 1 294 times in 310 load steps) is written
// to stderr once when first met and once with its count when the run's warnings are taken.
TEST(Log, ARepeatedWarningIsWrittenOnceAndCountedOnce)
{
  CapturedWarnings captured;
  for (int k = 1; k <= 100; ++k)
  {
    log::set_context("load step " + std::to_string(k) + ", outer iteration 1");
    log::warning("rows are dependent");
  }
  const std::vector<std::string> taken = log::take_warnings();
  EXPECT_EQ(captured.text.str(),
            "warning: rows are dependent\n"
            "warning: rows are dependent (100 times, first at load step 1, outer iteration 1, "
            "last at load step 100, outer iteration 1)\n");
  ASSERT_EQ(taken.size(), 1u);
}

// Warnings logged from the threads of a subdomain loop at once each stay one line on stderr:
// written piece by piece, two ran together into one line and an empty one (a fuzz mutant of
// CalculiX's plate, two one-cell bodies taking their kernels from K on the two threads).
TEST(Log, WarningsFromThreadsStayWholeLines)
{
  CapturedWarnings captured;
  constexpr int per_thread = 2000;
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t)
    threads.emplace_back([t] {
      for (int k = 0; k < per_thread; ++k)
        log::warning("thread " + std::to_string(t) + " warning " + std::to_string(k) + std::string(60, 'x'));
    });
  for (std::thread& thread : threads)
    thread.join();
  log::take_warnings();
  std::istringstream lines(captured.text.str());
  int count = 0;
  for (std::string line; std::getline(lines, line); ++count)
    ASSERT_TRUE(line.starts_with("warning: thread ") && line.ends_with(std::string(60, 'x')) &&
                line.find("warning:", 1) == std::string::npos)
        << "line " << count << ": " << line;
  EXPECT_EQ(count, 4 * per_thread);
}
