#pragma once
/// @file The abstract linear operator y = A x that solvers see (MFEM Operator, PETSc Mat).

#include "la/types.hpp"

#include <chrono>

namespace feticon::la
{
class VectorSpace;

/// A square linear operator applied to vectors of its space; solvers know nothing else about
/// it.
class LinearOperator
{
public:
  virtual ~LinearOperator() = default;
  /// Number of rows (= columns) on this rank.
  virtual Index size() const = 0;
  /// y = A x; `y` is resized by the implementation.
  virtual void apply(const Vector& x, Vector& y) const = 0;
  /// Reductions (dot products, norms) of its vectors when they are distributed over ranks,
  /// as the FETI dual vectors are; nullptr: all entries are local. Not owned.
  virtual const VectorSpace* space() const { return nullptr; }
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

/// Counts the applications of an operator and the wall time spent in them, so that the cost
/// of a solver's iteration can be compared with that of its operator (bench/).
class TimedOperator : public LinearOperator
{
public:
  explicit TimedOperator(const LinearOperator& A) : _A(A) {}
  Index size() const override { return _A.size(); }
  const VectorSpace* space() const override { return _A.space(); }
  void apply(const Vector& x, Vector& y) const override
  {
    const auto start = std::chrono::steady_clock::now();
    _A.apply(x, y);
    _seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    ++_applications;
  }
  double seconds() const { return _seconds; }
  int64_t applications() const { return _applications; }

private:
  const LinearOperator& _A;
  mutable double _seconds = 0;
  mutable int64_t _applications = 0;
};
} // namespace feticon::la
