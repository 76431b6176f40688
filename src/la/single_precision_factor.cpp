#include "la/single_precision_factor.hpp"

#include "common/error.hpp"

#include <algorithm>

#include <immintrin.h>

namespace feticon::la
{
namespace
{
// The two kernels of the substitutions, on float entries with double sums. The build does not
// assume a CPU (no -march), so the AVX2/FMA versions are picked at run time; they are what
// makes the halved memory traffic show (scalar conversions made the solves compute-bound).

__attribute__((target("avx2,fma"))) double dot_avx2(const float* a, const double* b, Index n)
{
  __m256d s0 = _mm256_setzero_pd(), s1 = _mm256_setzero_pd();
  Index i = 0;
  for (; i + 8 <= n; i += 8)
  {
    s0 = _mm256_fmadd_pd(_mm256_cvtps_pd(_mm_loadu_ps(a + i)), _mm256_loadu_pd(b + i), s0);
    s1 = _mm256_fmadd_pd(_mm256_cvtps_pd(_mm_loadu_ps(a + i + 4)), _mm256_loadu_pd(b + i + 4), s1);
  }
  alignas(32) double lanes[4];
  _mm256_store_pd(lanes, _mm256_add_pd(s0, s1));
  double sum = (lanes[0] + lanes[1]) + (lanes[2] + lanes[3]);
  for (; i < n; ++i)
    sum += static_cast<double>(a[i]) * b[i];
  return sum;
}

__attribute__((target("avx2,fma"))) void subtract_scaled_avx2(double* y, const float* a, double alpha, Index n)
{
  const __m256d minus_alpha = _mm256_set1_pd(-alpha);
  Index i = 0;
  for (; i + 4 <= n; i += 4)
    _mm256_storeu_pd(y + i, _mm256_fmadd_pd(_mm256_cvtps_pd(_mm_loadu_ps(a + i)), minus_alpha, _mm256_loadu_pd(y + i)));
  for (; i < n; ++i)
    y[i] -= static_cast<double>(a[i]) * alpha;
}

/// y -= A x for a block A (rows x cols) of a packed lower trapezoid: column j + 1 starts
/// `step - j` entries after column j (a packed column is one entry shorter than the one
/// before it). Four columns a pass, so that y is read and written once per four columns.
__attribute__((target("avx2,fma"))) void subtract_product_avx2(double* y, const float* A, Index step, Index rows,
                                                               Index cols, const double* x)
{
  Index j = 0;
  for (; j + 4 <= cols; j += 4)
  {
    const float *a0 = A, *a1 = a0 + step, *a2 = a1 + step - 1, *a3 = a2 + step - 2;
    A = a3 + step - 3;
    step -= 4;
    const __m256d x0 = _mm256_set1_pd(x[j]), x1 = _mm256_set1_pd(x[j + 1]);
    const __m256d x2 = _mm256_set1_pd(x[j + 2]), x3 = _mm256_set1_pd(x[j + 3]);
    Index i = 0;
    for (; i + 4 <= rows; i += 4)
    {
      __m256d t = _mm256_mul_pd(_mm256_cvtps_pd(_mm_loadu_ps(a0 + i)), x0);
      t = _mm256_fmadd_pd(_mm256_cvtps_pd(_mm_loadu_ps(a1 + i)), x1, t);
      t = _mm256_fmadd_pd(_mm256_cvtps_pd(_mm_loadu_ps(a2 + i)), x2, t);
      t = _mm256_fmadd_pd(_mm256_cvtps_pd(_mm_loadu_ps(a3 + i)), x3, t);
      _mm256_storeu_pd(y + i, _mm256_sub_pd(_mm256_loadu_pd(y + i), t));
    }
    for (; i < rows; ++i)
      y[i] -= static_cast<double>(a0[i]) * x[j] + static_cast<double>(a1[i]) * x[j + 1] +
          static_cast<double>(a2[i]) * x[j + 2] + static_cast<double>(a3[i]) * x[j + 3];
  }
  for (; j < cols; ++j, A += step--)
    subtract_scaled_avx2(y, A, x[j], rows);
}

/// x -= A' y for the same packed block: four dot products a pass, sharing the loads of y.
__attribute__((target("avx2,fma"))) void subtract_transposed_product_avx2(double* x, const float* A, Index step,
                                                                          Index rows, Index cols, const double* y)
{
  Index j = 0;
  for (; j + 4 <= cols; j += 4)
  {
    const float *a0 = A, *a1 = a0 + step, *a2 = a1 + step - 1, *a3 = a2 + step - 2;
    A = a3 + step - 3;
    step -= 4;
    __m256d s0 = _mm256_setzero_pd(), s1 = _mm256_setzero_pd(), s2 = _mm256_setzero_pd(), s3 = _mm256_setzero_pd();
    Index i = 0;
    for (; i + 4 <= rows; i += 4)
    {
      const __m256d yi = _mm256_loadu_pd(y + i);
      s0 = _mm256_fmadd_pd(_mm256_cvtps_pd(_mm_loadu_ps(a0 + i)), yi, s0);
      s1 = _mm256_fmadd_pd(_mm256_cvtps_pd(_mm_loadu_ps(a1 + i)), yi, s1);
      s2 = _mm256_fmadd_pd(_mm256_cvtps_pd(_mm_loadu_ps(a2 + i)), yi, s2);
      s3 = _mm256_fmadd_pd(_mm256_cvtps_pd(_mm_loadu_ps(a3 + i)), yi, s3);
    }
    // Horizontal sums of the four accumulators at once.
    const __m256d h01 = _mm256_hadd_pd(s0, s1), h23 = _mm256_hadd_pd(s2, s3);
    __m256d sums = _mm256_add_pd(_mm256_permute2f128_pd(h01, h23, 0x20), _mm256_permute2f128_pd(h01, h23, 0x31));
    alignas(32) double lanes[4];
    _mm256_store_pd(lanes, sums);
    for (; i < rows; ++i)
    {
      lanes[0] += static_cast<double>(a0[i]) * y[i];
      lanes[1] += static_cast<double>(a1[i]) * y[i];
      lanes[2] += static_cast<double>(a2[i]) * y[i];
      lanes[3] += static_cast<double>(a3[i]) * y[i];
    }
    for (int c = 0; c < 4; ++c)
      x[j + c] -= lanes[c];
  }
  for (; j < cols; ++j, A += step--)
    x[j] -= dot_avx2(A, y, rows);
}

double dot_scalar(const float* a, const double* b, Index n)
{
  double s0 = 0, s1 = 0;
  Index i = 0;
  for (; i + 2 <= n; i += 2)
  {
    s0 += static_cast<double>(a[i]) * b[i];
    s1 += static_cast<double>(a[i + 1]) * b[i + 1];
  }
  for (; i < n; ++i)
    s0 += static_cast<double>(a[i]) * b[i];
  return s0 + s1;
}

void subtract_scaled_scalar(double* y, const float* a, double alpha, Index n)
{
  for (Index i = 0; i < n; ++i)
    y[i] -= static_cast<double>(a[i]) * alpha;
}

void subtract_product_scalar(double* y, const float* A, Index step, Index rows, Index cols, const double* x)
{
  for (Index j = 0; j < cols; ++j, A += step--)
    subtract_scaled_scalar(y, A, x[j], rows);
}

void subtract_transposed_product_scalar(double* x, const float* A, Index step, Index rows, Index cols, const double* y)
{
  for (Index j = 0; j < cols; ++j, A += step--)
    x[j] -= dot_scalar(A, y, rows);
}

/// The CPU's features, read once; __builtin_cpu_init first because this initializer may run
/// before libgcc's own constructor has filled them in.
bool cpu_has_avx2()
{
  __builtin_cpu_init();
  return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
}

bool has_avx2 = cpu_has_avx2(); // use_vector_kernels() may turn them off

/// y -= A x (A: float, packed columns, the first `step` entries apart).
void subtract_product(double* y, const float* A, Index step, Index rows, Index cols, const double* x)
{
  if (has_avx2)
    subtract_product_avx2(y, A, step, rows, cols, x);
  else
    subtract_product_scalar(y, A, step, rows, cols, x);
}

/// x -= A' y.
void subtract_transposed_product(double* x, const float* A, Index step, Index rows, Index cols, const double* y)
{
  if (has_avx2)
    subtract_transposed_product_avx2(x, A, step, rows, cols, y);
  else
    subtract_transposed_product_scalar(x, A, step, rows, cols, y);
}
} // namespace

bool use_vector_kernels(bool on)
{
  has_avx2 = on && cpu_has_avx2();
  return has_avx2;
}

SinglePrecisionFactor::SinglePrecisionFactor(const cholmod_factor& L)
{
  FETICON_CHECK(L.is_super && L.is_ll && L.xtype == CHOLMOD_REAL && L.dtype == CHOLMOD_DOUBLE && L.itype == CHOLMOD_INT,
                "a single-precision copy needs a supernodal real LL' factor with int indices");
  const auto n = static_cast<size_t>(L.n);
  const auto nsuper = static_cast<size_t>(L.nsuper);
  const int* perm = static_cast<const int*>(L.Perm);
  _permutation.assign(perm, perm + n);
  const int* super = static_cast<const int*>(L.super);
  const int* pi = static_cast<const int*>(L.pi);
  const int* px = static_cast<const int*>(L.px);
  _first_column.assign(super, super + nsuper + 1);
  _row_start.assign(pi, pi + nsuper + 1);
  _rows.assign(static_cast<const int*>(L.s), static_cast<const int*>(L.s) + pi[nsuper]);
  // Only the lower trapezoid of each supernode's dense block is read: packed, column j from
  // its diagonal down (CHOLMOD's upper triangles were 18 % of the entries on hertz3d).
  _value_start.resize(nsuper + 1);
  _value_start[0] = 0;
  for (size_t k = 0; k < nsuper; ++k)
  {
    const long ncol = super[k + 1] - super[k], nrow = pi[k + 1] - pi[k];
    _value_start[k + 1] = _value_start[k] + ncol * nrow - ncol * (ncol - 1) / 2;
    _max_rows = std::max<Index>(_max_rows, nrow);
  }
  const double* x = static_cast<const double*>(L.x);
  _values.resize(static_cast<size_t>(_value_start[nsuper]));
  float* packed = _values.data();
  for (size_t k = 0; k < nsuper; ++k)
  {
    const long ncol = super[k + 1] - super[k], nrow = pi[k + 1] - pi[k];
    for (long j = 0; j < ncol; ++j)
      packed = std::transform(x + px[k] + j * nrow + j, x + px[k] + (j + 1) * nrow, packed,
                              [](double v) { return static_cast<float>(v); });
  }
}

/// Columns of a supernode's triangle taken at once: the width of the product kernels.
constexpr Index panel = 4;

SinglePrecisionFactor::Supernode SinglePrecisionFactor::supernode(size_t k) const
{
  Supernode out;
  out.first = _first_column[k];
  out.ncol = _first_column[k + 1] - out.first;
  out.nrow = _row_start[k + 1] - _row_start[k];
  out.below = out.nrow - out.ncol;
  out.block = _values.data() + _value_start[k];
  out.below_rows = _rows.data() + _row_start[k] + out.ncol;
  return out;
}

void SinglePrecisionFactor::forward(double* y, double* work) const
{
  for (size_t k = 0; k + 1 < _first_column.size(); ++k)
  {
    const Supernode node = supernode(k);
    const Index ncol = node.ncol, below = node.below;
    const int* rows = node.below_rows;
    double* yk = y + node.first;
    // The diagonal triangle in panels of `panel` columns, then the rows below into a dense
    // workspace: one pass over each for every four columns.
    for (Index j0 = 0; j0 < ncol; j0 += panel)
    {
      const Index width = std::min(panel, ncol - j0);
      for (Index j = j0; j < j0 + width; ++j)
      {
        const float* column = node.diagonal(j);
        yk[j] /= static_cast<double>(column[0]);
        for (Index i = j + 1; i < j0 + width; ++i)
          yk[i] -= static_cast<double>(column[i - j]) * yk[j];
      }
      const Index rest = ncol - j0 - width;
      subtract_product(yk + j0 + width, node.diagonal(j0) + width, node.step(j0), rest, width, yk + j0);
    }
    std::fill(work, work + below, 0.0);
    subtract_product(work, node.diagonal(0) + ncol, node.step(0), below, ncol, yk);
    for (Index i = 0; i < below; ++i)
      y[rows[i]] += work[i];
  }
}

void SinglePrecisionFactor::backward(double* y, double* work) const
{
  for (size_t k = _first_column.size() - 1; k-- > 0;)
  {
    const Supernode node = supernode(k);
    const Index ncol = node.ncol, below = node.below;
    const int* rows = node.below_rows;
    double* yk = y + node.first;
    for (Index i = 0; i < below; ++i)
      work[i] = y[rows[i]];
    subtract_transposed_product(yk, node.diagonal(0) + ncol, node.step(0), below, ncol, work);
    for (Index j0 = (ncol - 1) / panel * panel; j0 >= 0; j0 -= panel)
    {
      const Index width = std::min(panel, ncol - j0);
      const Index rest = ncol - j0 - width;
      subtract_transposed_product(yk + j0, node.diagonal(j0) + width, node.step(j0), rest, width, yk + j0 + width);
      for (Index j = j0 + width - 1; j >= j0; --j)
      {
        const float* column = node.diagonal(j);
        double sum = 0;
        for (Index i = j + 1; i < j0 + width; ++i)
          sum += static_cast<double>(column[i - j]) * yk[i];
        yk[j] = (yk[j] - sum) / static_cast<double>(column[0]);
      }
    }
  }
}

Vector SinglePrecisionFactor::solve(const Vector& b) const
{
  FETICON_ASSERT(b.size() == size(), "single-precision factor applied to a vector of the wrong size");
  const Index n = size();
  Vector y(n);
  for (Index k = 0; k < n; ++k)
    y(k) = b(_permutation[static_cast<size_t>(k)]);
  std::vector<double> work(static_cast<size_t>(_max_rows));
  forward(y.data(), work.data());
  backward(y.data(), work.data());
  Vector x(n);
  for (Index k = 0; k < n; ++k)
    x(_permutation[static_cast<size_t>(k)]) = y(k);
  return x;
}

Matrix SinglePrecisionFactor::solve(const Matrix& B) const
{
  Matrix X(B.rows(), B.cols());
  for (Index j = 0; j < B.cols(); ++j)
    X.col(j) = solve(Vector(B.col(j)));
  return X;
}
} // namespace feticon::la
