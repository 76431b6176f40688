/// la::symmetric_product (BLAS dsymv) reads only the triangle it is told to. Reference: Eigen's
/// general product with the full symmetric matrix; the other triangle holds NaN, which would
/// spread into y if it were read.
#include "la/symmetric_product.hpp"

#include <gtest/gtest.h>

#include <limits>

namespace feticon::la
{
namespace
{
TEST(SymmetricProduct, ReadsOnlyItsTriangle)
{
  for (const Index n : {0, 1, 7, 300})
  {
    Matrix A = Matrix::Random(n, n);
    A = (A + A.transpose()).eval();
    const Vector x = Vector::Random(n);
    const Vector reference = A * x;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (const Triangle triangle : {Triangle::lower, Triangle::upper})
    {
      Matrix half = A;
      for (Index c = 0; c < n; ++c)
        for (Index r = 0; r < n; ++r)
          if (triangle == Triangle::lower ? r < c : r > c)
            half(r, c) = nan;
      Vector y;
      symmetric_product(half, triangle, x, y);
      ASSERT_EQ(y.size(), n);
      EXPECT_LE((y - reference).norm(), 1e-13 * (1 + reference.norm())) << "n " << n;
    }
  }
}
} // namespace
} // namespace feticon::la
