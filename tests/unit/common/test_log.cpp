/// log::warning keeps its lines for take_warnings() (common/log.hpp), which run summaries list.
/// Reference: the definition: each line once, in the order first logged, then cleared.

#include "common/log.hpp"

#include <gtest/gtest.h>

using namespace feticon;

TEST(Log, WarningsAreKeptOnceUntilTaken)
{
  log::take_warnings(); // whatever earlier tests logged
  const log::Level level = log::level();
  log::set_level(log::Level::quiet); // kept even when not printed
  log::warning("first");
  log::warning("second");
  log::warning("first");
  log::set_level(level);
  EXPECT_EQ(log::take_warnings(), (std::vector<std::string>{"first", "second"}));
  EXPECT_TRUE(log::take_warnings().empty());
}
