#include "fem/finite_j2_plasticity.hpp"

#include "common/error.hpp"
#include "fem/voigt.hpp"

#include <cmath>

namespace feticon::fem
{
namespace
{
/// What a yielded point's return leaves for the positive tangent (finite_j2_return).
struct Yielded
{
  double mu_bar = 0, theta = 1, theta_bar = 0;
  Voigt direction = Voigt::Zero(); ///< the trial deviator's, plain shears, unit in the Voigt contraction
};

/// |X|_C = sqrt(tr((X C)^2)): the norm of the push-forward of a reference-configuration tensor.
double pushed_norm(const Eigen::Matrix3d& X, const Eigen::Matrix3d& C)
{
  const Eigen::Matrix3d XC = X * C;
  return std::sqrt(std::max(0.0, (XC * XC).trace()));
}

/// The update of a kinematically hardening point (file comment), from the trial deviator S_tr.
J2Update kinematic_update(const Material& material, const PlasticPointState& committed, const Eigen::Matrix3d& C,
                          const Eigen::Matrix3d& Ci, double J, const Eigen::Matrix3d& S_tr, double Ie, Yielded* yielded)
{
  const double mu = material.lame_mu(), bulk = material.young / (3 * (1 - 2 * material.poisson));
  const double j23 = std::cbrt(J * J);
  const Eigen::Matrix3d beta_iso = tensor_of(committed.back_stress) / j23;
  const double beta_trace = C.cwiseProduct(beta_iso).sum() / 3;
  const Eigen::Matrix3d xi = S_tr - (beta_iso - beta_trace * Ci);
  const double q = std::sqrt(1.5) * pushed_norm(xi, C);
  const YieldCurve& curve = material.plastic;
  const double eqps = committed.equivalent_plastic_strain;
  J2Update out{Voigt::Zero(), committed, false};
  Eigen::Matrix3d S_dev = S_tr;
  if (q > J * curve.stress.front() * (1 + 1e-10))
  {
    const double mu_bar = mu * Ie - beta_trace, scale = J * mu_bar / mu;
    FETICON_CHECK(mu_bar > 0,
                  "a kinematically hardening point's back stress exceeds its shear stiffness (mu_bar = " << mu_bar
                                                                                                         << " Pa)");
    // q - 3 mu_bar d = J sigma_y(0) + scale (sigma_y(eqps + d) - sigma_y(eqps)), as plastic_increment solves it.
    const double d =
        plastic_increment(curve, mu_bar, q - J * curve.stress.front() + scale * curve.yield_stress(eqps), eqps, scale);
    const double rise = scale * (curve.yield_stress(eqps + d) - curve.yield_stress(eqps));
    if (yielded)
    {
      const double theta = 1 - 3 * mu_bar * d / q;
      const Voigt n = voigt_of(xi);
      *yielded = {mu_bar, theta, 1 / (1 + scale * curve.hardening(eqps + d) / (3 * mu_bar)) - (1 - theta),
                  n / std::sqrt(n.head<3>().squaredNorm() + 2 * n.tail<3>().squaredNorm())};
    }
    S_dev -= 3 * mu_bar * d / q * xi;
    out.plastic = true;
    out.state.equivalent_plastic_strain = eqps + d;
    out.state.plastic_strain -= voigt_of(3 * mu_bar * d / (mu * q) * j23 * xi);
    out.state.back_stress += voigt_of(rise / q * j23 * xi);
  }
  out.stress = voigt_of(bulk * (J * J - 1) / 2 * Ci + S_dev);
  return out;
}

/// The update without the tangent (file comment).
J2Update update(const Material& material, const Voigt& strain, const PlasticPointState& committed,
                Yielded* yielded = nullptr)
{
  const Eigen::Matrix3d C = right_cauchy_green(strain);
  const double det = C.determinant();
  FETICON_CHECK(det > 0, "a plastic point is inverted: det C = " << det);
  const double J = std::sqrt(det), j23 = std::cbrt(det); // J^(2/3)
  const Eigen::Matrix3d Ci = C.inverse();
  const double mu = material.lame_mu(), bulk = material.young / (3 * (1 - 2 * material.poisson));
  const Eigen::Matrix3d Cb = (Eigen::Matrix3d::Identity() + tensor_of(committed.plastic_strain)) / j23;
  const double Ie = (C.cwiseProduct(Cb)).sum() / 3;
  Eigen::Matrix3d S_dev = mu * (Cb - Ie * Ci);
  if (material.plastic.kinematic)
    return kinematic_update(material, committed, C, Ci, J, S_dev, Ie, yielded);
  const Eigen::Matrix3d SC = S_dev * C;
  const double q = std::sqrt(1.5 * std::max(0.0, (SC * SC).trace()));
  const double eqps = committed.equivalent_plastic_strain;
  J2Update out{Voigt::Zero(), committed, false};
  // Within 1e-10 of the yield stress the point is elastic (j2_return says why).
  if (q > J * material.plastic.yield_stress(eqps) * (1 + 1e-10))
  {
    const double mu_bar = mu * Ie;
    const double d = plastic_increment(material.plastic, mu_bar, q, eqps, J);
    if (yielded)
    {
      const double theta = 1 - 3 * mu_bar * d / q;
      const Voigt n = voigt_of(S_dev);
      *yielded = {mu_bar, theta, 1 / (1 + J * material.plastic.hardening(eqps + d) / (3 * mu_bar)) - (1 - theta),
                  n / std::sqrt(n.head<3>().squaredNorm() + 2 * n.tail<3>().squaredNorm())};
    }
    S_dev *= 1 - 3 * mu_bar * d / q;
    out.plastic = true;
    out.state.equivalent_plastic_strain = eqps + d;
    out.state.plastic_strain = voigt_of(j23 * (S_dev / mu + Ie * Ci) - Eigen::Matrix3d::Identity());
  }
  out.stress = voigt_of(bulk * (det - 1) / 2 * Ci + S_dev);
  return out;
}

/// The pulled-back positive tangent of a yielded point (finite_j2_return's comment).
Eigen::Matrix<double, 6, 6> positive_tangent(const Material& material, const Voigt& strain, const Yielded& yielded)
{
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(right_cauchy_green(strain));
  const Eigen::Matrix3d Q = eigen.eigenvectors();
  const Eigen::Vector3d stretch = eigen.eigenvalues().cwiseSqrt();
  const Eigen::Matrix3d U = Q * stretch.asDiagonal() * Q.transpose();
  const Eigen::Matrix3d Ui = Q * stretch.cwiseInverse().asDiagonal() * Q.transpose();
  const double J = stretch.prod(), bulk = material.young / (3 * (1 - 2 * material.poisson)), G = yielded.mu_bar;
  // The deviator's direction in the frame of U: U S_tr U, S_tr along yielded.direction.
  const Voigt n = voigt_of(U * tensor_of(yielded.direction) * U);
  const Voigt unit_n = n / std::sqrt(n.head<3>().squaredNorm() + 2 * n.tail<3>().squaredNorm());
  Eigen::Matrix<double, 6, 6> c = Eigen::Matrix<double, 6, 6>::Zero(); // engineering shears in, plain out
  c.topLeftCorner<3, 3>().setConstant(bulk * J * J - 2 * G * yielded.theta / 3);
  c.topLeftCorner<3, 3>().diagonal().array() += 2 * G * yielded.theta;
  c.bottomRightCorner<3, 3>().diagonal().setConstant(G * yielded.theta);
  c -= 2 * G * yielded.theta_bar * unit_n * unit_n.transpose();
  // L on stresses (plain shears: basis e_i e_j + e_j e_i for a shear) and on strains
  // (engineering shears: basis (e_i e_j + e_j e_i) / 2, shears doubled on the way out).
  Eigen::Matrix<double, 6, 6> L_stress, L_strain;
  for (int k = 0; k < 6; ++k)
  {
    Voigt unit = Voigt::Zero();
    unit(k) = 1;
    L_stress.col(k) = voigt_of(Ui * tensor_of(unit) * Ui);
    Voigt half = unit;
    half.tail<3>() *= 0.5;
    Voigt strain_out = voigt_of(Ui * tensor_of(half) * Ui);
    strain_out.tail<3>() *= 2;
    L_strain.col(k) = strain_out;
  }
  const Eigen::Matrix<double, 6, 6> out = L_stress * c * L_strain;
  return 0.5 * (out + out.transpose());
}
} // namespace

J2Update finite_j2_return(const Material& material, const Voigt& strain, const PlasticPointState& committed,
                          Eigen::Matrix<double, 6, 6>* tangent)
{
  Yielded yielded;
  const J2Update out = update(material, strain, committed, &yielded);
  if (!tangent)
    return out;
  constexpr double h = 1e-6;
  for (int k = 0; k < 6; ++k)
  {
    Voigt plus = strain, minus = strain;
    plus(k) += h;
    minus(k) -= h;
    tangent->col(k) = (update(material, plus, committed).stress - update(material, minus, committed).stress) / (2 * h);
  }
  *tangent = 0.5 * (*tangent + tangent->transpose()).eval();
  if (!out.plastic || Eigen::LLT<Eigen::Matrix<double, 6, 6>>(*tangent).info() == Eigen::Success)
    return out;
  // A yielded point whose exact dS/dE is not positive (the stress's own terms exceed what the
  // hardening leaves of the shear stiffness): the consistent tangent of the Kirchhoff stress
  // without those terms, K J^2 1 (x) 1 + 2 mu_bar theta I_dev - 2 mu_bar theta_bar n (x) n
  // (positive for H >= 0), pulled back to the reference configuration through U = sqrt(C): dS/dE
  // = L c L with L(X) = U^-1 X U^-1, n the trial deviator U S U / |U S U|.
  *tangent = positive_tangent(material, strain, yielded);
  return out;
}
} // namespace feticon::fem
