#include "fem/hyperelasticity.hpp"

#include "common/error.hpp"
#include "fem/voigt.hpp"

#include <cmath>

namespace feticon::fem
{
namespace
{
using Tangent = Eigen::Matrix<double, 6, 6>;

/// Voigt index -> tensor indices, [11,22,33,12,23,31].
constexpr int row_of[6] = {0, 1, 2, 0, 1, 2};
constexpr int col_of[6] = {0, 1, 2, 1, 2, 0};

/// d(C^-1)/dC = -I_Ci with I_Ci,ijkl = (Ci_ik Ci_jl + Ci_il Ci_jk) / 2, in Voigt order; with
/// engineering shears on the strain side a 4th-order tensor of minor symmetries maps to the
/// Voigt matrix of its components (no factors).
Tangent symmetric_product(const Eigen::Matrix3d& Ci)
{
  Tangent out;
  for (int a = 0; a < 6; ++a)
    for (int b = 0; b < 6; ++b)
    {
      const int i = row_of[a], j = col_of[a], k = row_of[b], l = col_of[b];
      out(a, b) = 0.5 * (Ci(i, k) * Ci(j, l) + Ci(i, l) * Ci(j, k));
    }
  return out;
}
} // namespace

double Hyperelastic::initial_young() const
{
  const double mu = initial_shear_modulus(), K = initial_bulk_modulus();
  return 9 * K * mu / (3 * K + mu);
}

double Hyperelastic::initial_poisson() const
{
  const double mu = initial_shear_modulus(), K = initial_bulk_modulus();
  return (3 * K - 2 * mu) / (6 * K + 2 * mu);
}

void Hyperelastic::check(const std::string& where) const
{
  FETICON_CHECK(std::isfinite(c10) && c10 > 0, where << ": C10 = " << c10 << " must be positive");
  FETICON_CHECK(std::isfinite(c01) && c01 >= 0, where << ": C01 = " << c01 << " must not be negative");
  FETICON_CHECK(std::isfinite(d1) && d1 > 0,
                where << ": D1 = " << d1 << " must be positive (2 / D1 is the bulk modulus; feticon has no "
                      << "incompressible formulation)");
}

Voigt hyperelastic_stress(const Hyperelastic& law, const Voigt& E, Tangent* tangent)
{
  const Eigen::Matrix3d C = right_cauchy_green(E);
  const double det = C.determinant();
  FETICON_CHECK(det > 0, "a hyperelastic point is inverted: det C = " << det);
  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
  const Eigen::Matrix3d Ci = C.inverse();
  const double J = std::sqrt(det);
  const double I1 = C.trace();
  const double I2 = 0.5 * (I1 * I1 - (C * C).trace());
  const double j23 = std::pow(J, -2.0 / 3.0), j43 = j23 * j23;
  const double c10 = law.c10, c01 = law.c01, K = 2 / law.d1; // (J - 1)^2 / D1 = K (J - 1)^2 / 2
  // S = 2 dW/dC: dI1b/dC = J^(-2/3) (I - I1/3 Ci), dI2b/dC = J^(-4/3) (I1 I - C - 2/3 I2 Ci),
  // dJ/dC = J/2 Ci.
  const Eigen::Matrix3d dI2 = I1 * I - C; // dI2/dC
  const Eigen::Matrix3d S =
      2 * c10 * j23 * (I - I1 / 3 * Ci) + 2 * c01 * j43 * (dI2 - 2.0 / 3.0 * I2 * Ci) + K * J * (J - 1) * Ci;
  if (tangent)
  {
    const Voigt i = voigt_of(I), ci = voigt_of(Ci), d2 = voigt_of(dI2);
    const Tangent Ici = symmetric_product(Ci);
    const Tangent II = Voigt(1, 1, 1, 0.5, 0.5, 0.5).asDiagonal(); // the symmetric identity
    // dS/dE = 2 dS/dC, term by term of S.
    Tangent& D = *tangent;
    D = 4 * c10 * j23 * (I1 / 9 * ci * ci.transpose() - (i * ci.transpose() + ci * i.transpose()) / 3 + I1 / 3 * Ici);
    D += 4 * c01 * j43 *
        (i * i.transpose() - II - 2.0 / 3.0 * (d2 * ci.transpose() + ci * d2.transpose()) +
         4.0 / 9.0 * I2 * ci * ci.transpose() + 2.0 / 3.0 * I2 * Ici);
    D += K * ((2 * J - 1) * J * ci * ci.transpose() - 2 * J * (J - 1) * Ici);
    D = 0.5 * (D + D.transpose()).eval(); // symmetric to round-off; made exactly so
  }
  return voigt_of(S);
}
} // namespace feticon::fem
