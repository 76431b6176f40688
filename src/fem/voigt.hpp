#pragma once
/// @file Symmetric tensors in Voigt form, the order [11, 22, 33, 12, 23, 31] every element and
/// material of fem uses: stresses with their shears as they are, strains with engineering shears
/// (twice the tensor's).

#include <Eigen/Dense>

namespace feticon::fem
{
using Voigt = Eigen::Matrix<double, 6, 1>;

/// The symmetric tensor of a Voigt vector with plain shears (a stress).
inline Eigen::Matrix3d tensor_of(const Voigt& v)
{
  Eigen::Matrix3d A;
  A << v(0), v(3), v(5), v(3), v(1), v(4), v(5), v(4), v(2);
  return A;
}

/// A symmetric tensor's components in Voigt order, shears as they are.
inline Voigt voigt_of(const Eigen::Matrix3d& A)
{
  return (Voigt() << A(0, 0), A(1, 1), A(2, 2), A(0, 1), A(1, 2), A(2, 0)).finished();
}

/// C = I + 2 E of a Green-Lagrange strain E given with engineering shears.
inline Eigen::Matrix3d right_cauchy_green(const Voigt& E)
{
  Eigen::Matrix3d C;
  C << 1 + 2 * E(0), E(3), E(5), E(3), 1 + 2 * E(1), E(4), E(5), E(4), 1 + 2 * E(2);
  return C;
}
} // namespace feticon::fem
