#pragma once
/// @file y = A x for a dense symmetric A stored in one triangle, by BLAS dsymv.
///
/// Why BLAS and not Eigen: the explicit FETI operators spend every MPRGP step in these
/// products, and they are bound by memory traffic. OpenBLAS's dsymv reads one triangle once
/// with vector kernels chosen for the CPU at run time, two to six times faster than Eigen's
/// general product in our build (docs/measurements.md). Reading one triangle also lets two symmetric matrices share
/// one square array (decomposition/explicit_boundary_operators.hpp).

#include "la/types.hpp"

namespace feticon::la
{
enum class Triangle
{
  lower, ///< the diagonal and below
  upper  ///< the diagonal and above
};

/// y = A x with A symmetric, read from `triangle` of the square column-major `A` only.
void symmetric_product(const Matrix& A, Triangle triangle, const Vector& x, Vector& y);
} // namespace feticon::la
