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

RowSpring row_spring(const fem::NormalLaw& law, double area, double row_norm, double c)
{
  const fem::NormalLaw::Tangent line = law.tangent(-row_norm * c);
  return {line.stiffness * area * row_norm * row_norm, line.zero_overclosure / row_norm};
}

double law_area(const contact::ContactConstraints& rows, la::Index i, const fem::NormalLaw& law)
{
  const auto row = static_cast<size_t>(i);
  return law.on_master_face && rows.master_face_area[row] > 0 ? rows.master_face_area[row] : rows.slave_area[row];
}

void law_springs(const contact::ContactConstraints& rows, const fem::NormalLaw& law, la::Vector& stiffness,
                 la::Vector& shift)
{
  stiffness.resize(rows.n_rows());
  shift.resize(rows.n_rows());
  for (la::Index i = 0; i < stiffness.size(); ++i)
  {
    const RowSpring spring = row_spring(law, law_area(rows, i, law), rows.row_norm[i], rows.c(i));
    stiffness(i) = spring.stiffness;
    shift(i) = spring.shift;
  }
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
