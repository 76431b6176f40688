#include "la/cholmod.hpp"

#include "common/error.hpp"

#include <Eigen/CholmodSupport>

#include <algorithm>
#include <mutex>

namespace feticon::la
{
struct CholmodFactor::Impl
{
  Eigen::CholmodDecomposition<SparseMatrix, Eigen::Lower> solver;
};

CholmodFactor::CholmodFactor() = default;
CholmodFactor::~CholmodFactor() = default;
CholmodFactor::CholmodFactor(CholmodFactor&&) noexcept = default;
CholmodFactor& CholmodFactor::operator=(CholmodFactor&&) noexcept = default;

void CholmodFactor::factorize(const SparseMatrix& A, const char* what)
{
  FETICON_CHECK(A.rows() == A.cols(), what << " is not square (" << A.rows() << " x " << A.cols() << ")");
  _impl = std::make_unique<Impl>();
  // CHOLMOD picks simplicial (small subdomains: no BLAS call overhead) or supernodal.
  _impl->solver.setMode(Eigen::CholmodAuto);
  {
    // One analysis at a time: CHOLMOD's default ordering also tries METIS when AMD fills in
    // much (3D subdomains), and METIS keeps its random generator in a global; two threads
    // ordering at once drew from it in a timing-dependent order, so the orderings, and with
    // them the round-off of every later step, changed from run to run (hertz3d at 97k DOFs:
    // three runs, three peak pressures differing in the 7th digit). The numeric
    // factorization, most of the time, stays on the threads.
    static std::mutex analysis;
    const std::lock_guard lock(analysis);
    _impl->solver.analyzePattern(A);
  }
  _impl->solver.factorize(A);
  if (_impl->solver.info() != Eigen::Success)
  {
    _impl.reset();
    FETICON_CHECK(false,
                  "Cholesky factorization of " << what
                                               << " failed: the matrix is not positive "
                                                  "definite (a body or subdomain may be "
                                                  "unsupported)");
  }
}

Vector CholmodFactor::solve(const Vector& b) const
{
  FETICON_ASSERT(_impl, "solve before factorize");
  return _impl->solver.solve(b);
}

Matrix CholmodFactor::solve(const Matrix& B) const
{
  FETICON_ASSERT(_impl, "solve before factorize");
  Matrix X(B.rows(), B.cols());
  for (Index j = 0; j < B.cols(); j += solve_block) // a block of right-hand sides in cache
  {
    const Index width = std::min(solve_block, B.cols() - j);
    X.middleCols(j, width) = _impl->solver.solve(Matrix(B.middleCols(j, width)));
  }
  return X;
}

long CholmodFactor::factor_nonzeros() const
{
  if (!_impl)
    return 0;
  // Eigen exposes the cholmod_factor; for a supernodal factor xsize counts the entries.
  auto& factor = const_cast<Eigen::CholmodDecomposition<SparseMatrix, Eigen::Lower>&>(_impl->solver);
  cholmod_common& common = factor.cholmod();
  return static_cast<long>(common.lnz);
}
} // namespace feticon::la
