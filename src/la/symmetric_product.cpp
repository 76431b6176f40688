#include "la/symmetric_product.hpp"

#include "common/error.hpp"

#include <cblas.h>
#include <limits>

namespace feticon::la
{
void symmetric_product(const Matrix& A, Triangle triangle, const Vector& x, Vector& y)
{
  FETICON_ASSERT(A.rows() == A.cols() && x.size() == A.rows(), "symmetric_product: sizes");
  FETICON_ASSERT(A.rows() <= std::numeric_limits<int>::max(), "symmetric_product: BLAS takes int sizes");
  const int n = static_cast<int>(A.rows());
  y.resize(n);
  if (n == 0)
    return;
  cblas_dsymv(CblasColMajor, triangle == Triangle::lower ? CblasLower : CblasUpper, n, 1.0, A.data(), n, x.data(), 1,
              0.0, y.data(), 1);
}
} // namespace feticon::la
