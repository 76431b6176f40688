#pragma once
/// @file The abstract linear operator y = A x that solvers see (MFEM Operator, PETSc Mat).

#include "la/types.hpp"

namespace feticon::la
{
/// A square linear operator applied to vectors; solvers know nothing else about it.
class LinearOperator
{
public:
  virtual ~LinearOperator() = default;
  /// Number of rows (= columns).
  virtual Index size() const = 0;
  /// y = A x; `y` is resized by the implementation.
  virtual void apply(const Vector& x, Vector& y) const = 0;
};

/// A LinearOperator backed by an explicit sparse matrix (not owned).
class SparseOperator : public LinearOperator
{
public:
  explicit SparseOperator(const SparseMatrix& matrix) : _matrix(matrix) {}
  Index size() const override { return _matrix.rows(); }
  void apply(const Vector& x, Vector& y) const override { y = _matrix * x; }

private:
  const SparseMatrix& _matrix;
};
} // namespace feticon::la
