#include "la/cholmod.hpp"

#include "common/error.hpp"
#include "la/metis_random.hpp"
#include "la/nodal_ordering.hpp"
#include "la/single_precision_factor.hpp"

#include <Eigen/CholmodSupport>

#include <algorithm>
#include <mutex>

namespace feticon::la
{
namespace
{
/// Matrices from this size on are ordered by their node graph (nodal_ordering.hpp).
constexpr Index nodal_ordering_dofs = 3000;

/// Eigen keeps CHOLMOD's factor to itself; the single-precision copy reads it.
class Decomposition : public Eigen::CholmodDecomposition<SparseMatrix, Eigen::Lower>
{
public:
  const cholmod_factor& factor() const { return *m_cholmodFactor; }
  /// Whether the analysis gave a factor: Eigen's analyzePattern reports success whatever
  /// cholmod_analyze returned, and its factorize then reads a null factor.
  bool analyzed() const { return m_cholmodFactor != nullptr; }

  /// analyzePattern with the ordering `perm` (CHOLMOD's Perm), postordered by CHOLMOD.
  void analyze_given(const SparseMatrix& A, std::vector<int>& perm)
  {
    if (m_cholmodFactor)
      cholmod_free_factor(&m_cholmodFactor, &cholmod());
    cholmod_sparse view = Eigen::viewAsCholmod(A.selfadjointView<Eigen::Lower>());
    const int methods = cholmod().nmethods, ordering = cholmod().method[0].ordering;
    cholmod().nmethods = 1;
    cholmod().method[0].ordering = CHOLMOD_GIVEN;
    m_cholmodFactor = cholmod_analyze_p(&view, perm.data(), nullptr, 0, &cholmod());
    cholmod().nmethods = methods;
    cholmod().method[0].ordering = ordering;
    m_isInitialized = true;
    m_info = m_cholmodFactor ? Eigen::Success : Eigen::NumericalIssue;
    m_analysisIsOk = m_cholmodFactor != nullptr;
    m_factorizationIsOk = false;
  }
};
} // namespace

struct CholmodFactor::Impl
{
  std::unique_ptr<Decomposition> solver;         ///< null once copied to `single`
  std::unique_ptr<SinglePrecisionFactor> single; ///< FactorPrecision::single_precision
  long nonzeros = 0;
  double reciprocal_condition = 0;
};

CholmodFactor::CholmodFactor() = default;
CholmodFactor::~CholmodFactor() = default;
CholmodFactor::CholmodFactor(CholmodFactor&&) noexcept = default;
CholmodFactor& CholmodFactor::operator=(CholmodFactor&&) noexcept = default;

void CholmodFactor::factorize(const SparseMatrix& A, const char* what, FactorPrecision precision)
{
  FETICON_CHECK(A.rows() == A.cols(), what << " is not square (" << A.rows() << " x " << A.cols() << ")");
  _impl = std::make_unique<Impl>();
  _impl->solver = std::make_unique<Decomposition>();
  Decomposition& solver = *_impl->solver;
  // CHOLMOD picks simplicial (small subdomains: no BLAS call overhead) or supernodal.
  solver.setMode(Eigen::CholmodAuto);
  solver.cholmod().print = 0; // a failure is reported by the checks below, in one line
  {
    // The ordering is METIS's (nodal_ordering.hpp; CHOLMOD's default also tries METIS when
    // AMD fills in much, as on 3D subdomains), and METIS draws from the C library's one
    // random generator: with the draws private to each thread the analyses run in parallel
    // and order as in a serial run; where they cannot be (metis_random.hpp) they run one at
    // a time, since interleaved draws changed the orderings, and with them the round-off of
    // every later step, from run to run (hertz3d at 97k DOFs: three runs, three peak
    // pressures differing in the 7th digit).
    const ThreadPrivateRandom private_draws;
    static std::mutex analysis;
    std::unique_lock lock(analysis, std::defer_lock);
    if (!thread_private_random_available())
      lock.lock();
    std::optional<std::vector<int>> nodal = nodal_nested_dissection(A, nodal_ordering_dofs);
    if (nodal)
      solver.analyze_given(A, *nodal);
    else
      solver.analyzePattern(A);
  }
  if (solver.info() != Eigen::Success || !solver.analyzed())
  {
    const int status = solver.cholmod().status;
    _impl.reset();
    FETICON_CHECK(
        false, "CHOLMOD could not analyze " << what << " (status " << status << "; -4: an input it takes for invalid)");
  }
  solver.factorize(A);
  if (solver.info() != Eigen::Success)
  {
    _impl.reset();
    FETICON_CHECK(false,
                  "Cholesky factorization of " << what
                                               << " failed: the matrix is not positive "
                                                  "definite (a body or subdomain may be "
                                                  "unsupported)");
  }
  // A simplicial factor is LDL' (CholmodAuto), which CHOLMOD computes for an indefinite matrix
  // as well (only a zero pivot stops it): D > 0 is what makes A positive definite. (A
  // hyperelastic subdomain's indefinite K_M passed here and made MPRGP fail; supernodal LL'
  // fails by itself.)
  if (const cholmod_factor& L = solver.factor(); !L.is_super && !L.is_ll)
  {
    const auto* p = static_cast<const int*>(L.p);
    const auto* x = static_cast<const double*>(L.x);
    for (size_t j = 0; j < L.n; ++j)
      if (!(x[p[j]] > 0))
      {
        const size_t n = L.n; // L lives in _impl
        _impl.reset();
        FETICON_CHECK(false,
                      "Cholesky factorization of " << what << " failed: the matrix is not positive definite "
                                                   << "(pivot " << j << " of " << n << ")");
      }
  }
  // For a supernodal factor CHOLMOD's lnz counts the entries.
  _impl->nonzeros = static_cast<long>(solver.cholmod().lnz);
  _impl->reciprocal_condition = cholmod_rcond(const_cast<cholmod_factor*>(&solver.factor()), &solver.cholmod());
  if (precision == FactorPrecision::single_precision && solver.factor().is_super)
  {
    _impl->single = std::make_unique<SinglePrecisionFactor>(solver.factor());
    _impl->solver.reset(); // the double factor is not needed any more
  }
}

bool CholmodFactor::single_precision() const { return _impl && _impl->single; }

Vector CholmodFactor::solve(const Vector& b) const
{
  FETICON_ASSERT(_impl, "solve before factorize");
  if (_impl->single)
    return _impl->single->solve(b);
  return _impl->solver->solve(b);
}

Matrix CholmodFactor::solve(const Matrix& B) const
{
  FETICON_ASSERT(_impl, "solve before factorize");
  if (_impl->single)
    return _impl->single->solve(B);
  Matrix X(B.rows(), B.cols());
  for (Index j = 0; j < B.cols(); j += solve_block) // a block of right-hand sides in cache
  {
    const Index width = std::min(solve_block, B.cols() - j);
    X.middleCols(j, width) = _impl->solver->solve(Matrix(B.middleCols(j, width)));
  }
  return X;
}

double CholmodFactor::reciprocal_condition() const { return _impl ? _impl->reciprocal_condition : 0.0; }

long CholmodFactor::factor_nonzeros() const { return _impl ? _impl->nonzeros : 0; }
} // namespace feticon::la
