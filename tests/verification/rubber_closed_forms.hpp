#pragma once
/// Closed forms of CalculiX's hyperelastic laws (fem/hyperelasticity.hpp) under homogeneous
/// deformations, written in principal stretches, independently of the code's S(E):
/// the Cauchy stress of W(I1b, I2b) + K (J - 1)^2 / 2 is (Holzapfel, Nonlinear Solid Mechanics,
/// 6.4-6.6)
///   sigma = 2 / J dev[(C10 + I1b C01) Bb - C01 Bb^2] + K (J - 1) I,  Bb = J^(-2/3) F F'.

#include "fem/hyperelasticity.hpp"

#include <Eigen/Dense>

#include <cmath>

namespace rubber_closed_forms
{
/// sigma at deformation gradient F.
inline Eigen::Matrix3d cauchy_stress(const feticon::fem::Hyperelastic& law, const Eigen::Matrix3d& F)
{
  const double J = F.determinant();
  const Eigen::Matrix3d Bb = std::pow(J, -2.0 / 3.0) * F * F.transpose();
  const Eigen::Matrix3d tau = 2 * ((law.c10 + Bb.trace() * law.c01) * Bb - law.c01 * Bb * Bb);
  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
  return (tau - tau.trace() / 3 * I) / J + law.initial_bulk_modulus() * (J - 1) * I;
}

/// Uniaxial stress along x at axial stretch `stretch`: the lateral stretch where sigma_yy = 0
/// (bisection to round-off; sigma_yy grows with the lateral stretch).
inline double uniaxial_lateral_stretch(const feticon::fem::Hyperelastic& law, double stretch)
{
  double low = 0.2, high = 5;
  for (int k = 0; k < 200; ++k)
  {
    const double mid = 0.5 * (low + high);
    const Eigen::Matrix3d F = Eigen::Vector3d(stretch, mid, mid).asDiagonal();
    (cauchy_stress(law, F)(1, 1) > 0 ? high : low) = mid;
  }
  return 0.5 * (low + high);
}

/// The nominal stress (force per reference area) of uniaxial stress at `stretch`:
/// sigma_xx times the current over the reference area, lateral stretch squared.
inline double uniaxial_nominal_stress(const feticon::fem::Hyperelastic& law, double stretch)
{
  const double lateral = uniaxial_lateral_stretch(law, stretch);
  const Eigen::Matrix3d F = Eigen::Vector3d(stretch, lateral, lateral).asDiagonal();
  return cauchy_stress(law, F)(0, 0) * lateral * lateral;
}
} // namespace rubber_closed_forms
