#include "nonlinear/contact_penalty.hpp"

namespace feticon::nonlinear
{
la::Vector row_penalties(const contact::ContactConstraints& rows, double eps_n)
{
  const la::Vector area =
      Eigen::Map<const la::Vector>(rows.slave_area.data(), static_cast<la::Index>(rows.slave_area.size()));
  const double mean = area.size() > 0 ? area.mean() : 1.0;
  return area * (eps_n / mean);
}

la::Vector law_penalties(const contact::ContactConstraints& rows, double slope)
{
  la::Vector out(rows.n_rows());
  for (la::Index i = 0; i < out.size(); ++i)
    out(i) = slope * rows.slave_area[i] * rows.row_norm[i] * rows.row_norm[i];
  return out;
}

la::Vector law_shifts(const contact::ContactConstraints& rows, const fem::NormalLaw& law)
{
  la::Vector out(rows.n_rows());
  for (la::Index i = 0; i < out.size(); ++i)
    out(i) = law.sigma_inf / (law.slope * rows.row_norm[i]);
  return out;
}

void penalty_terms(const contact::ContactConstraints& rows, const std::vector<char>& active, const la::Vector& eps,
                   la::SparseMatrix& K_pen, la::Vector& f_pen)
{
  using RowMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;
  std::vector<la::Triplet> triplets;
  la::Vector c_A = la::Vector::Zero(rows.c.size());
  for (int r = 0; r < rows.B.outerSize(); ++r)
    if (active[r])
    {
      c_A(r) = eps(r) * rows.c(r);
      for (RowMatrix::InnerIterator it(rows.B, r); it; ++it)
        triplets.emplace_back(r, static_cast<int>(it.col()), it.value());
    }
  la::SparseMatrix B_A(rows.B.rows(), rows.B.cols());
  B_A.setFromTriplets(triplets.begin(), triplets.end());
  K_pen = la::SparseMatrix(B_A.transpose() * eps.asDiagonal() * B_A);
  f_pen = B_A.transpose() * c_A;
}
} // namespace feticon::nonlinear
