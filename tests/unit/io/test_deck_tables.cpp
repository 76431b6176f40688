/// @file The reader's bookkeeping tables (io/deck_data.hpp): the deck label -> index map in
/// its three forms (no table for 1..n, a dense table, a hash map for far labels) and the
/// run-length node and element sets. Reference: the maps these tables stand for, built by
/// std::map and std::vector from the same inputs.

#include "io/deck_data.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <vector>

namespace feticon::io
{
namespace
{
TEST(DeckTables, LabelIndexMatchesAMapThroughEveryForm)
{
  // 1..5 in order (no table), then a gap, a label below, a far label (hash map) and repeats.
  const std::vector<int64_t> labels = {1, 2, 3, 4, 5, 9, 7, 6, 3'000'000'000LL, 8, 5, 9, 3'000'000'000LL, 0};
  LabelIndex index;
  index.reserve(10);
  std::map<int64_t, int32_t> reference;
  int32_t next = 0;
  for (const int64_t label : labels)
  {
    const bool fresh = reference.emplace(label, next).second;
    EXPECT_EQ(index.insert(label, next), fresh) << "label " << label;
    if (fresh)
      ++next;
    for (int64_t probe = -1; probe <= 12; ++probe)
    {
      const auto it = reference.find(probe);
      EXPECT_EQ(index.find(probe), it == reference.end() ? -1 : it->second) << "after " << label << ", probe " << probe;
    }
    EXPECT_EQ(index.find(3'000'000'000LL), reference.count(3'000'000'000LL) ? reference.at(3'000'000'000LL) : -1);
  }
}

TEST(DeckTables, LabelIndexWithoutTableWhileLabelsAreIndexPlusOne)
{
  LabelIndex index;
  for (int32_t i = 0; i < 1000; ++i)
    ASSERT_TRUE(index.insert(i + 1, i));
  EXPECT_FALSE(index.insert(500, 1000)); // defined twice
  EXPECT_EQ(index.find(1000), 999);
  EXPECT_EQ(index.find(1001), -1);
  EXPECT_EQ(index.find(0), -1);
  EXPECT_TRUE(index.insert(1001, 1000));
  EXPECT_EQ(index.find(1001), 1000);
}

TEST(DeckTables, IndexRunsKeepOrderRepeatsAndCompact)
{
  const std::vector<int32_t> members = {4, 5, 6, 7, 2, 3, 3, 10, 11, 0};
  IndexRuns runs;
  runs.append(members);
  EXPECT_EQ(runs.size(), static_cast<int64_t>(members.size()));
  EXPECT_EQ(runs.expand(), members);

  // A set that names itself doubles; compact() sorts and unifies it past 2 n + 1024 members.
  IndexRuns doubling;
  doubling.append({3, 1, 2});
  for (int k = 0; k < 12; ++k)
  {
    doubling.append(doubling.expand());
    doubling.compact(3);
  }
  EXPECT_LE(doubling.size(), 2 * 3 + 1024);
  std::vector<int32_t> seen = doubling.expand();
  std::sort(seen.begin(), seen.end());
  seen.erase(std::unique(seen.begin(), seen.end()), seen.end());
  EXPECT_EQ(seen, (std::vector<int32_t>{1, 2, 3}));
}
} // namespace
} // namespace feticon::io
