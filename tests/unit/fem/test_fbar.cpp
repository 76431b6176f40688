/// F-bar on the linear cells of hyperelastic bodies (issue 66, item 4; fem/cell_element.cpp):
/// the internal force against central differences of the cell's energy written here from its
/// definition (CalculiX's Mooney-Rivlin strain energy of F_bar = (J_0 / J)^(1/d) F, J_0 the mean
/// of J over the cell's reference volume), K_M symmetric with the rigid motions in its kernel,
/// and a homogeneous deformation, where F_bar = F, against the cell without F-bar.

#include "fem/cell_element.hpp"
#include "fem/material.hpp"
#include "fem/reference_element.hpp"
#include "mesh/cell_type.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

using namespace feticon;

namespace fbar_cells
{
struct Case
{
  mesh::CellKind kind;
  mesh::PlanarKind planar;
};
const std::vector<Case> cases = {{mesh::CellKind::hex8, mesh::PlanarKind::none},
                                 {mesh::CellKind::quad4, mesh::PlanarKind::plane_strain},
                                 {mesh::CellKind::quad4, mesh::PlanarKind::axisymmetric}};

fem::Material rubber(bool fbar)
{
  fem::Material m;
  m.set_hyperelastic({0.8e6, 0.2e6, 4.0e-10}); // mu_0 2 MPa, K_0 5 GPa: K_0 / mu_0 = 2500
  m.fbar = fbar;
  return m;
}

/// A distorted cell (r from 0.01 m in axisymmetry) and displacements: a finite stretch and
/// rotation plus a non-homogeneous part of `wobble` m.
std::pair<Eigen::MatrixX3d, Eigen::MatrixX3d> deformed_cell(const Case& c, double wobble)
{
  const auto& nodes = mesh::cell_type(c.kind).reference_nodes;
  Eigen::Matrix3d A;
  A << 1, 0.1, 0.05, 0.02, 0.9, 0.1, 0.03, 0.04, 1.1;
  Eigen::Matrix3d F = Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix() *
      Eigen::Vector3d(1.15, 0.95, 0.92).asDiagonal();
  const bool planar = c.planar != mesh::PlanarKind::none;
  if (planar)
  {
    A.row(2).setZero();
    F = Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ()).toRotationMatrix() *
        Eigen::Vector3d(1.15, 0.9, 1).asDiagonal();
  }
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> d(-wobble, wobble);
  Eigen::MatrixX3d X(nodes.size(), 3), u(nodes.size(), 3);
  for (size_t a = 0; a < nodes.size(); ++a)
  {
    X.row(a) = 0.005 * (A * Eigen::Vector3d(nodes[a][0], nodes[a][1], nodes[a][2])).transpose();
    X(a, 0) += 0.01;
    u.row(a) = ((F - Eigen::Matrix3d::Identity()) * X.row(a).transpose()).transpose();
    u.row(a) += Eigen::RowVector3d(d(rng), d(rng), planar ? 0.0 : d(rng));
  }
  if (c.planar == mesh::PlanarKind::axisymmetric) // a radial scaling: u_r proportional to r
    for (size_t a = 0; a < nodes.size(); ++a)
      u.row(a) = Eigen::RowVector3d(0.1 * X(a, 0) + d(rng), -0.05 * X(a, 1) + d(rng), 0);
  return {X, u};
}

/// The deformation gradient at reference point xi (2D: F_33 = 1, or 1 + u_r / r), and the
/// point's w det J times the out-of-plane measure (2 pi r, or the thickness 1).
std::pair<Eigen::Matrix3d, double> gradient(const Case& c, const Eigen::MatrixX3d& X, const Eigen::MatrixX3d& u,
                                            const Eigen::Vector3d& xi, double weight)
{
  const Eigen::VectorXd N = fem::shape_values(c.kind, xi);
  const Eigen::MatrixX3d dN = fem::shape_gradients(c.kind, xi);
  Eigen::Matrix3d F = Eigen::Matrix3d::Identity();
  if (c.planar == mesh::PlanarKind::none)
  {
    const Eigen::Matrix3d J = X.transpose() * dN;
    F += u.transpose() * (dN * J.inverse());
    return {F, weight * J.determinant()};
  }
  const Eigen::Matrix2d J = X.leftCols<2>().transpose() * dN.leftCols<2>();
  F.topLeftCorner<2, 2>() += u.leftCols<2>().transpose() * (dN.leftCols<2>() * J.inverse());
  const double r = X.col(0).dot(N);
  if (c.planar == mesh::PlanarKind::axisymmetric)
    F(2, 2) += u.col(0).dot(N) / r;
  return {F, weight * J.determinant() * (c.planar == mesh::PlanarKind::axisymmetric ? 2 * std::numbers::pi * r : 1.0)};
}

/// CalculiX's Mooney-Rivlin energy C10 (I1b - 3) + C01 (I2b - 3) + (J - 1)^2 / D1 of F_bar,
/// summed over the cell's points: its derivative is the internal force.
double fbar_energy(const Case& c, const Eigen::MatrixX3d& X, const Eigen::MatrixX3d& u, const fem::Hyperelastic& law)
{
  const int d = c.planar == mesh::PlanarKind::plane_strain ? 2 : 3;
  const fem::QuadratureRule& rule = fem::quadrature(c.kind);
  double volume = 0, deformed = 0;
  for (size_t q = 0; q < rule.points.size(); ++q)
  {
    const auto [F, weight] = gradient(c, X, u, rule.points[q], rule.weights[q]);
    volume += weight;
    deformed += weight * F.determinant();
  }
  const double J_0 = deformed / volume;
  double energy = 0;
  for (size_t q = 0; q < rule.points.size(); ++q)
  {
    const auto [F, weight] = gradient(c, X, u, rule.points[q], rule.weights[q]);
    Eigen::Matrix3d F_bar = F;
    const double alpha = std::pow(J_0 / F.determinant(), 1.0 / d);
    if (d == 3)
      F_bar *= alpha;
    else
      F_bar.topLeftCorner<2, 2>() *= alpha;
    const double J = F_bar.determinant();
    const Eigen::Matrix3d C = F_bar.transpose() * F_bar;
    const double I1 = std::pow(J, -2.0 / 3) * C.trace();
    const double I2 = std::pow(J, -4.0 / 3) * 0.5 * (C.trace() * C.trace() - (C * C).trace());
    energy += weight * (law.c10 * (I1 - 3) + law.c01 * (I2 - 3) + (J - 1) * (J - 1) / law.d1);
  }
  return energy;
}

Eigen::VectorXd internal_force(const Case& c, const Eigen::MatrixX3d& X, const Eigen::MatrixX3d& u,
                               const fem::Material& material, Eigen::MatrixXd* K = nullptr)
{
  Eigen::VectorXd f;
  fem::cell_element(c.kind, X, u, material, fem::Kinematics::total_lagrangian,
                    K ? fem::StiffnessKind::material : fem::StiffnessKind::none, fem::Integration::full, f, K, 0,
                    nullptr, nullptr, {c.planar, 1.0});
  return f;
}

std::string name(const Case& c)
{
  return std::string(mesh::cell_type(c.kind).name) + " " + std::string(mesh::planar_name(c.planar));
}
} // namespace fbar_cells

using namespace fbar_cells;

// Reference: central differences (step 1e-8 m) of the energy written above from F_bar's
// definition; their error is about 1e-7 of the force.
TEST(FBar, InternalForceIsTheDerivativeOfTheCellsEnergy)
{
  const fem::Material material = rubber(true);
  for (const Case& c : cases)
  {
    const auto [X, u] = deformed_cell(c, 2e-4);
    const Eigen::VectorXd f = internal_force(c, X, u, material);
    const int components = c.planar == mesh::PlanarKind::none ? 3 : 2;
    const double h = 1e-8;
    for (Eigen::Index a = 0; a < X.rows(); ++a)
      for (int i = 0; i < components; ++i)
      {
        Eigen::MatrixX3d up = u, um = u;
        up(a, i) += h;
        um(a, i) -= h;
        const double derivative =
            (fbar_energy(c, X, up, material.hyperelastic) - fbar_energy(c, X, um, material.hyperelastic)) / (2 * h);
        EXPECT_NEAR(f(3 * a + i), derivative, 1e-6 * f.norm()) << name(c) << ", node " << a << ", " << i;
      }
    // And F-bar changes the force of this non-homogeneous deformation: the test compares two
    // different things.
    EXPECT_GT((internal_force(c, X, u, rubber(false)) - f).norm(), 1e-3 * f.norm()) << name(c);
  }
}

// Reference: a homogeneous deformation (axisymmetry: u_r = 0.1 r, u_z = -0.05 z) has J = J_0 at
// every point, so F_bar = F and the force is the standard cell's (to round-off).
TEST(FBar, HomogeneousDeformationGivesTheStandardCell)
{
  for (const Case& c : cases)
  {
    const auto [X, u] = deformed_cell(c, 0);
    const Eigen::VectorXd standard = internal_force(c, X, u, rubber(false));
    EXPECT_LE((internal_force(c, X, u, rubber(true)) - standard).norm(), 1e-10 * standard.norm()) << name(c);
  }
}

// Reference: K_M = int B_bar' C B_bar is symmetric and strains nothing along the rigid motions
// of the current configuration (FETI's kernel): translations and rotations about z (3D: all
// three axes; axisymmetry: the axial translation only).
TEST(FBar, MaterialStiffnessIsSymmetricWithTheRigidMotionsAsKernel)
{
  for (const Case& c : cases)
  {
    const auto [X, u] = deformed_cell(c, 2e-4);
    Eigen::MatrixXd K;
    internal_force(c, X, u, rubber(true), &K);
    EXPECT_LE((K - K.transpose()).norm(), 1e-12 * K.norm()) << name(c);
    const Eigen::MatrixX3d x = X + u;
    std::vector<Eigen::VectorXd> modes;
    for (int i = 0; i < 3; ++i)
    {
      Eigen::VectorXd translation = Eigen::VectorXd::Zero(3 * X.rows()), rotation = translation;
      for (Eigen::Index a = 0; a < X.rows(); ++a)
      {
        translation(3 * a + i) = 1;
        rotation.segment<3>(3 * a) = Eigen::Vector3d::Unit(i).cross(x.row(a).transpose());
      }
      const bool in_plane_rotation = i == 2;
      if (c.planar == mesh::PlanarKind::none || (c.planar == mesh::PlanarKind::plane_strain && i < 2) ||
          (c.planar == mesh::PlanarKind::axisymmetric && i == 1))
        modes.push_back(translation);
      if (c.planar == mesh::PlanarKind::none || (c.planar == mesh::PlanarKind::plane_strain && in_plane_rotation))
        modes.push_back(rotation);
    }
    for (const Eigen::VectorXd& mode : modes)
      EXPECT_LE((K * mode).norm(), 1e-9 * K.norm() * mode.norm()) << name(c);
  }
}

// F-bar on a finite-strain J2 cell (plasticity.fbar): a homogeneous deformation beyond yield
// (the distorted cell stretched 15 %, sigma_y = 250 MPa against stresses of GPa) has F_bar = F, so
// the force and every point's returned state are the standard cell's (to round-off); a
// non-homogeneous one differs (the test compares two different things).
TEST(FBar, PlasticCellOfAHomogeneousDeformationIsTheStandardCell)
{
  for (const Case& c : cases)
  {
    fem::Material steel(210e9, 0.3);
    steel.plastic.stress = {250e6, 450e6};
    steel.plastic.plastic_strain = {0., 0.5};
    const size_t n_points = fem::quadrature(c.kind).points.size();
    const std::vector<fem::PlasticPointState> committed(n_points);
    const auto run = [&](const Eigen::MatrixX3d& X, const Eigen::MatrixX3d& u, bool fbar,
                         std::vector<fem::PlasticPointState>& updated) {
      steel.fbar = fbar;
      updated.assign(n_points, {});
      const fem::CellPlasticState plastic{committed, updated};
      Eigen::VectorXd f;
      fem::cell_element(c.kind, X, u, steel, fem::Kinematics::total_lagrangian, fem::StiffnessKind::none,
                        fem::Integration::full, f, nullptr, 0, nullptr, &plastic, {c.planar, 1.0});
      return f;
    };
    std::vector<fem::PlasticPointState> standard_states, fbar_states;
    const auto [X, u] = deformed_cell(c, 0);
    const Eigen::VectorXd standard = run(X, u, false, standard_states);
    EXPECT_LE((run(X, u, true, fbar_states) - standard).norm(), 1e-10 * standard.norm()) << name(c);
    for (size_t q = 0; q < n_points; ++q)
    {
      EXPECT_GT(standard_states[q].equivalent_plastic_strain, 0.01) << name(c) << ": the point should yield";
      EXPECT_NEAR(fbar_states[q].equivalent_plastic_strain, standard_states[q].equivalent_plastic_strain, 1e-12)
          << name(c);
    }
    const auto [Xw, uw] = deformed_cell(c, 2e-4);
    EXPECT_GT((run(Xw, uw, true, fbar_states) - run(Xw, uw, false, standard_states)).norm(), 1e-4 * standard.norm())
        << name(c);
  }
}
