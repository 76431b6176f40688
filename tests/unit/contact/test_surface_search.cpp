/// Tests of SurfaceSearch. Reference: brute force, i.e. testing the point against every box.

#include "contact/surface_search.hpp"

#include "common/error.hpp"

#include <gtest/gtest.h>

#include <random>

namespace feticon::contact
{
namespace
{
std::vector<int32_t> brute_force(const std::vector<BoundingBox>& boxes, const Eigen::Vector3d& p)
{
  std::vector<int32_t> ids;
  for (size_t k = 0; k < boxes.size(); ++k)
    if (boxes[k].contains(p))
      ids.push_back(static_cast<int32_t>(k));
  return ids;
}

BoundingBox box(const Eigen::Vector3d& lower, const Eigen::Vector3d& upper)
{
  BoundingBox b;
  b.extend(lower);
  b.extend(upper);
  return b;
}
} // namespace

TEST(SurfaceSearch, RandomBoxesMatchBruteForce)
{
  // Boxes of very different sizes (1e-3 .. 0.3, plus a few flat ones) in the unit cube.
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> unit(0, 1);
  std::vector<BoundingBox> boxes;
  for (int k = 0; k < 500; ++k)
  {
    const Eigen::Vector3d lower(unit(rng), unit(rng), unit(rng));
    Eigen::Vector3d size = Eigen::Vector3d(unit(rng), unit(rng), unit(rng)) * (k % 10 == 0 ? 0.3 : 0.03);
    if (k % 7 == 0)
      size(2) = 0; // flat box
    boxes.push_back(box(lower, lower + size));
  }
  const SurfaceSearch search(boxes);
  int64_t n_found = 0;
  std::vector<int32_t> found;
  for (int q = 0; q < 5000; ++q)
  {
    const Eigen::Vector3d p(-0.1 + 1.4 * unit(rng), -0.1 + 1.4 * unit(rng), -0.1 + 1.4 * unit(rng));
    search.candidates(p, found);
    ASSERT_EQ(found, brute_force(boxes, p)) << "query " << q;
    n_found += static_cast<int64_t>(found.size());
  }
  // About 6 % of the query volume is covered (50 boxes of mean volume 0.15^3 in 1.4^3): some
  // 300 hits, so the comparison is not vacuous.
  EXPECT_GT(n_found, 200);
  // Points on the faces of boxes (closed boxes), including flat ones.
  for (size_t k = 0; k < boxes.size(); k += 7)
  {
    EXPECT_EQ(search.candidates(boxes[k].lower), brute_force(boxes, boxes[k].lower));
    EXPECT_EQ(search.candidates(boxes[k].upper), brute_force(boxes, boxes[k].upper));
  }
  // Memory bound of the file comment.
  EXPECT_LE(search.n_entries(), 64 * search.n_boxes());
}

TEST(SurfaceSearch, OneHugeBoxAmongSmallOnesStaysBounded)
{
  std::vector<BoundingBox> boxes;
  for (int k = 0; k < 100; ++k)
    boxes.push_back(box(Eigen::Vector3d(0.01 * k, 0, 0), Eigen::Vector3d(0.01 * k + 1e-3, 1e-3, 1e-3)));
  boxes.push_back(box(Eigen::Vector3d(-100, -100, -100), Eigen::Vector3d(100, 100, 100)));
  const SurfaceSearch search(boxes);
  EXPECT_LE(search.n_entries(), 64 * search.n_boxes());
  const Eigen::Vector3d p(0.0505, 5e-4, 5e-4); // inside small box 5 and the huge box
  EXPECT_EQ(search.candidates(p), (std::vector<int32_t>{5, 100}));
  EXPECT_EQ(search.candidates(Eigen::Vector3d(50, 50, 50)), (std::vector<int32_t>{100}));
  EXPECT_TRUE(search.candidates(Eigen::Vector3d(1e9, 0, 0)).empty());
}

TEST(SurfaceSearch, EmptyAndInvalidBoxes)
{
  const SurfaceSearch empty(std::vector<BoundingBox>{});
  EXPECT_TRUE(empty.candidates(Eigen::Vector3d::Zero()).empty());
  EXPECT_THROW(SurfaceSearch(std::vector<BoundingBox>{BoundingBox{}}), Error);
}
} // namespace feticon::contact
