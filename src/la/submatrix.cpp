#include "la/submatrix.hpp"

#include "common/error.hpp"

namespace feticon::la
{
SparseMatrix principal_submatrix(const SparseMatrix& A, const std::vector<int32_t>& position,
                                 int32_t n_kept)
{
  FETICON_ASSERT(static_cast<Index>(position.size()) == A.rows() && A.rows() == A.cols(),
                 "position map does not match the matrix");
  std::vector<Triplet> triplets;
  triplets.reserve(A.nonZeros());
  for (int col = 0; col < A.outerSize(); ++col)
    if (position[col] >= 0)
      for (SparseMatrix::InnerIterator it(A, col); it; ++it)
        if (position[it.row()] >= 0)
          triplets.emplace_back(position[it.row()], position[col], it.value());
  SparseMatrix out(n_kept, n_kept);
  out.setFromTriplets(triplets.begin(), triplets.end());
  return out;
}
} // namespace feticon::la
