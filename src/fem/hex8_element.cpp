#include "fem/hex8_element.hpp"

#include "common/error.hpp"

#include <cmath>

namespace feticon::fem
{
namespace
{
using Voigt = Eigen::Matrix<double, 6, 1>;
using StrainDisplacement = Eigen::Matrix<double, 6, 24>;

/// B_NL at one Gauss point for deformation gradient Fd (Fd = I gives the linear B).
StrainDisplacement strain_displacement(const ShapeGradients& dN, const Eigen::Matrix3d& Fd)
{
  StrainDisplacement B;
  for (int a = 0; a < 8; ++a)
  {
    const double n1 = dN(a, 0), n2 = dN(a, 1), n3 = dN(a, 2);
    for (int i = 0; i < 3; ++i)
    {
      const int col = 3 * a + i;
      B(0, col) = Fd(i, 0) * n1;
      B(1, col) = Fd(i, 1) * n2;
      B(2, col) = Fd(i, 2) * n3;
      B(3, col) = Fd(i, 0) * n2 + Fd(i, 1) * n1;
      B(4, col) = Fd(i, 1) * n3 + Fd(i, 2) * n2;
      B(5, col) = Fd(i, 2) * n1 + Fd(i, 0) * n3;
    }
  }
  return B;
}

Eigen::Matrix3d voigt_to_tensor(const Voigt& s)
{
  Eigen::Matrix3d t;
  t << s(0), s(3), s(5), s(3), s(1), s(4), s(5), s(4), s(2);
  return t;
}

Voigt tensor_to_voigt(const Eigen::Matrix3d& t)
{
  Voigt s;
  s << t(0, 0), t(1, 1), t(2, 2), t(0, 1), t(1, 2), t(2, 0);
  return s;
}

/// Second Piola–Kirchhoff stress (TL) or Cauchy stress (linear) at one Gauss point,
/// together with the deformation gradient used in B.
struct PointState
{
  Eigen::Matrix3d Fd;
  Voigt S;
  Voigt strain; ///< small strain or Green-Lagrange E, engineering shears
};

/// The thermal normal stress alpha E / (1 - 2 nu) Delta T at Gauss point xi (0 without a
/// temperature change).
double thermal_stress_at(const Material& material, const NodeTemperatures* temperature_change,
                         const Eigen::Vector3d& xi)
{
  if (!temperature_change || material.expansion == 0)
    return 0;
  return material.thermal_stress() * hex8_shape(xi).dot(*temperature_change);
}

PointState point_state(const ShapeGradients& dN, const NodeCoords& u, const Eigen::Matrix<double, 6, 6>& D,
                       const Material& material, Kinematics kinematics, int64_t cell, double thermal_stress)
{
  const Eigen::Matrix3d grad_u = u.transpose() * dN; // du_i/dX_j
  PointState state;
  if (kinematics == Kinematics::linear)
  {
    state.Fd.setIdentity();
    Voigt eps;
    eps << grad_u(0, 0), grad_u(1, 1), grad_u(2, 2), grad_u(0, 1) + grad_u(1, 0), grad_u(1, 2) + grad_u(2, 1),
        grad_u(2, 0) + grad_u(0, 2);
    state.S = D * eps;
    state.S.head<3>().array() -= thermal_stress;
    state.strain = eps;
    return state;
  }
  state.Fd = Eigen::Matrix3d::Identity() + grad_u;
  // A non-positive det F means the element turned inside out: no physical state to continue
  // from (the load step is too large or the problem diverges).
  const double J = state.Fd.determinant();
  FETICON_CHECK(J > 0,
                "element " << cell << " is inverted in the deformed configuration (det F = " << J
                           << "); use more load steps or check the loads");
  const Eigen::Matrix3d E = 0.5 * (state.Fd.transpose() * state.Fd - Eigen::Matrix3d::Identity());
  const Eigen::Matrix3d S =
      material.lame_lambda() * E.trace() * Eigen::Matrix3d::Identity() + 2 * material.lame_mu() * E;
  state.S = tensor_to_voigt(S);
  state.S.head<3>().array() -= thermal_stress;
  state.strain << E(0, 0), E(1, 1), E(2, 2), 2 * E(0, 1), 2 * E(1, 2), 2 * E(2, 0);
  return state;
}
} // namespace

void hex8_element(const NodeCoords& X, const NodeCoords& u, const Material& material, Kinematics kinematics,
                  StiffnessKind kind, ElementVector& f, ElementMatrix* K, int64_t cell,
                  const NodeTemperatures* temperature_change)
{
  const Eigen::Matrix<double, 6, 6> D = material.elasticity_matrix();
  f.setZero();
  if (kind != StiffnessKind::none)
    K->setZero();
  for (const Eigen::Vector3d& xi : hex8_gauss_points())
  {
    const GaussGeometry geo = hex8_gauss_geometry(X, xi, cell);
    const PointState state =
        point_state(geo.dN_dX, u, D, material, kinematics, cell, thermal_stress_at(material, temperature_change, xi));
    const StrainDisplacement B = strain_displacement(geo.dN_dX, state.Fd);
    f.noalias() += B.transpose() * state.S * geo.weight_det_j;
    if (kind == StiffnessKind::none)
      continue;
    // B' D B: its upper triangle, coefficient by coefficient (Eigen's blocked product was
    // 10 % of hertz3d's set-up at these sizes), mirrored once after the last point.
    const StrainDisplacement DB = (D * geo.weight_det_j).lazyProduct(B);
    K->triangularView<Eigen::Upper>() += B.transpose().lazyProduct(DB);
    if (kind == StiffnessKind::tangent && kinematics == Kinematics::total_lagrangian)
    {
      // Geometric stiffness: (grad N_a' S grad N_b) I_3 for every node pair (a <= b here).
      const Eigen::Matrix<double, 8, 8> G =
          geo.dN_dX * voigt_to_tensor(state.S) * geo.dN_dX.transpose() * geo.weight_det_j;
      for (int a = 0; a < 8; ++a)
        for (int b = a; b < 8; ++b)
          for (int i = 0; i < 3; ++i)
            (*K)(3 * a + i, 3 * b + i) += G(a, b);
    }
  }
  if (kind != StiffnessKind::none)
    for (int j = 0; j < 24; ++j)
      for (int i = j + 1; i < 24; ++i)
        (*K)(i, j) = (*K)(j, i);
}

Hex8PointResults hex8_point_results(const NodeCoords& X, const NodeCoords& u, const Material& material,
                                    Kinematics kinematics, int64_t cell, const NodeTemperatures* temperature_change)
{
  const Eigen::Matrix<double, 6, 6> D = material.elasticity_matrix();
  Hex8PointResults out;
  for (size_t g = 0; g < 8; ++g)
  {
    const Eigen::Vector3d& xi = hex8_gauss_points()[g];
    const GaussGeometry geo = hex8_gauss_geometry(X, xi, cell);
    const PointState state =
        point_state(geo.dN_dX, u, D, material, kinematics, cell, thermal_stress_at(material, temperature_change, xi));
    out.stress[g] = state.S;
    if (kinematics == Kinematics::total_lagrangian)
    {
      const double J = state.Fd.determinant(); // > 0, checked in point_state
      out.stress[g] = tensor_to_voigt(state.Fd * voigt_to_tensor(state.S) * state.Fd.transpose() / J);
    }
    out.strain[g] = state.strain;
    out.weight[g] = geo.weight_det_j;
  }
  return out;
}

Eigen::Matrix<double, 6, 1> hex8_cauchy_stress(const NodeCoords& X, const NodeCoords& u, const Material& material,
                                               Kinematics kinematics, int64_t cell,
                                               const NodeTemperatures* temperature_change)
{
  const Hex8PointResults points = hex8_point_results(X, u, material, kinematics, cell, temperature_change);
  Voigt sum = Voigt::Zero();
  double volume = 0;
  for (size_t g = 0; g < 8; ++g)
  {
    sum += points.stress[g] * points.weight[g];
    volume += points.weight[g];
  }
  return sum / volume;
}

double von_mises(const Eigen::Matrix<double, 6, 1>& s)
{
  const double d01 = s(0) - s(1), d12 = s(1) - s(2), d20 = s(2) - s(0);
  return std::sqrt(0.5 * (d01 * d01 + d12 * d12 + d20 * d20) + 3 * (s(3) * s(3) + s(4) * s(4) + s(5) * s(5)));
}
} // namespace feticon::fem
