#include "la/schur_complement.hpp"

#include "common/error.hpp"

#include <suitesparse/cholmod.h>

#include <algorithm>
#include <limits>

extern "C"
{
  // LAPACK (Debian's liblapack.so.3, served by OpenBLAS like the BLAS).
  void dpotrf_(const char* uplo, const int* n, double* a, const int* lda, int* info);
  void dpotri_(const char* uplo, const int* n, double* a, const int* lda, int* info);
  void dlauum_(const char* uplo, const int* n, double* a, const int* lda, int* info);
}

namespace feticon::la
{
namespace
{
/// One cholmod_common for one factorization, finished on every path.
class CholmodCommon
{
public:
  CholmodCommon() { cholmod_start(&common); }
  ~CholmodCommon()
  {
    if (factor)
      cholmod_free_factor(&factor, &common);
    cholmod_finish(&common);
  }
  CholmodCommon(const CholmodCommon&) = delete;
  CholmodCommon& operator=(const CholmodCommon&) = delete;

  cholmod_common common{};
  cholmod_factor* factor = nullptr;
};

/// CHOLMOD's view of the lower triangle of `lower` (compressed, 32-bit indices).
cholmod_sparse view_lower(SparseMatrix& lower)
{
  cholmod_sparse A{};
  A.nrow = A.ncol = static_cast<size_t>(lower.rows());
  A.nzmax = static_cast<size_t>(lower.nonZeros());
  A.p = lower.outerIndexPtr();
  A.i = lower.innerIndexPtr();
  A.x = lower.valuePtr();
  A.stype = -1;
  A.itype = CHOLMOD_INT;
  A.xtype = CHOLMOD_REAL;
  A.dtype = CHOLMOD_DOUBLE;
  A.sorted = 1;
  A.packed = 1;
  return A;
}
} // namespace

Matrix schur_complement(const SparseMatrix& A, const std::vector<int32_t>& boundary, const char* what)
{
  FETICON_ASSERT(A.rows() == A.cols() && A.rows() <= std::numeric_limits<int>::max(), "schur_complement: sizes");
  const int n = static_cast<int>(A.rows());
  const int nb = static_cast<int>(boundary.size());
  std::vector<int> member(n, 0); // CAMD constraint sets: 0 interior (first), 1 boundary (last)
  for (int32_t dof : boundary)
  {
    FETICON_ASSERT(dof >= 0 && dof < n && member[dof] == 0, "schur_complement: boundary DOFs must be distinct");
    member[dof] = 1;
  }
  if (nb == 0)
    return Matrix(0, 0);

  Vector shift(nb); // D = diag(A_bb)
  for (int k = 0; k < nb; ++k)
  {
    shift(k) = A.coeff(boundary[k], boundary[k]);
    FETICON_CHECK(shift(k) > 0, what << ": diagonal entry " << boundary[k] << " is not positive");
  }
  SparseMatrix lower = A.triangularView<Eigen::Lower>();
  for (int k = 0; k < nb; ++k)
    lower.coeffRef(boundary[k], boundary[k]) += shift(k);
  lower.makeCompressed();
  cholmod_sparse view = view_lower(lower);

  CholmodCommon c;
  c.common.print = 0;                       // errors are reported by the checks below
  c.common.supernodal = CHOLMOD_SUPERNODAL; // the trailing block is dense: BLAS 3
  c.common.nmethods = 1;
  c.common.method[0].ordering = CHOLMOD_GIVEN;
  c.common.postorder = 0; // a postorder may move boundary columns before interior ones
  std::vector<int> perm(n);
  FETICON_CHECK(cholmod_camd(&view, nullptr, 0, member.data(), perm.data(), &c.common),
                what << ": CAMD ordering failed (CHOLMOD status " << c.common.status << ")");
  c.factor = cholmod_analyze_p(&view, perm.data(), nullptr, 0, &c.common);
  FETICON_CHECK(c.factor, what << ": CHOLMOD analysis failed (status " << c.common.status << ")");
  cholmod_factorize(&view, c.factor, &c.common);
  FETICON_CHECK(c.common.status == CHOLMOD_OK && c.factor->minor == static_cast<size_t>(n),
                what << ": Cholesky factorization failed at column " << c.factor->minor << " of " << n
                     << " (the interior block is not positive definite)");
  FETICON_CHECK(c.factor->is_super, what << ": CHOLMOD returned a simplicial factor");

  // Position of each boundary DOF among the trailing columns of the factor.
  const int first = n - nb;
  const int* order = static_cast<const int*>(c.factor->Perm);
  std::vector<int> trailing(n, -1);
  for (int k = first; k < n; ++k)
  {
    FETICON_CHECK(member[order[k]] == 1, what << ": the factor's ordering does not end with the boundary");
    trailing[order[k]] = k - first;
  }

  // The trailing block, index-reversed: U(nb-1-r, nb-1-j) = L(first+r, first+j) is upper
  // triangular, and LAPACK's dlauum forms U U' = J (L_bb L_bb') J in a third of a full product.
  Matrix U = Matrix::Zero(nb, nb);
  const int* super = static_cast<const int*>(c.factor->super);
  const int* pi = static_cast<const int*>(c.factor->pi);
  const int* px = static_cast<const int*>(c.factor->px);
  const int* rows = static_cast<const int*>(c.factor->s);
  const double* values = static_cast<const double*>(c.factor->x);
  for (size_t sn = 0; sn < c.factor->nsuper; ++sn)
  {
    const int k1 = super[sn], k2 = super[sn + 1];
    if (k2 <= first)
      continue;
    const int nsrow = pi[sn + 1] - pi[sn];
    const int* row = rows + pi[sn];
    const double* block = values + px[sn]; // nsrow x (k2 - k1), column-major
    for (int j = std::max(k1, first); j < k2; ++j)
      for (int t = j - k1; t < nsrow; ++t) // rows j, j+1, ... of column j (row[t] >= j)
        U(n - 1 - row[t], n - 1 - j) = block[static_cast<ptrdiff_t>(j - k1) * nsrow + t];
  }
  int info = 0;
  dlauum_("U", &nb, U.data(), &nb, &info);
  FETICON_CHECK(info == 0, what << ": LAPACK dlauum failed (info " << info << ")");

  Matrix S(nb, nb);
  for (int k = 0; k < nb; ++k)
    for (int l = 0; l < nb; ++l)
    {
      const int p = nb - 1 - trailing[boundary[k]], q = nb - 1 - trailing[boundary[l]];
      S(k, l) = U(std::min(p, q), std::max(p, q));
    }
  S.diagonal() -= shift;
  return S;
}

void invert_spd(Matrix& A, const char* what)
{
  FETICON_ASSERT(A.rows() == A.cols() && A.rows() <= std::numeric_limits<int>::max(), "invert_spd: sizes");
  const int n = static_cast<int>(A.rows());
  if (n == 0)
    return;
  int info = 0;
  dpotrf_("L", &n, A.data(), &n, &info);
  FETICON_CHECK(info == 0, what << " is not positive definite (Cholesky pivot " << info << " of " << n << ")");
  dpotri_("L", &n, A.data(), &n, &info);
  FETICON_CHECK(info == 0, what << ": LAPACK dpotri failed (info " << info << ")");
  A.triangularView<Eigen::StrictlyUpper>() = A.transpose();
}
} // namespace feticon::la
