/// Patch tests on a distorted 2x2x2 mesh (ALGORITHMS.md 7, check 1), through the sparse
/// assembler, Dirichlet elimination and CHOLMOD.

#include "common/error.hpp"
#include "fem/assembler.hpp"
#include "fem/dirichlet.hpp"
#include "fem/loads.hpp"
#include "fem/stress.hpp"
#include "fem_test_meshes.hpp"
#include "la/cholmod.hpp"

#include <gtest/gtest.h>

using namespace feticon;

namespace
{
/// Exact field u = A X + c at every node.
la::Vector linear_field(const mesh::Mesh& m, const Eigen::Matrix3d& A, const Eigen::Vector3d& c)
{
  la::Vector u(3 * m.n_nodes());
  for (int n = 0; n < m.n_nodes(); ++n)
    u.segment<3>(3 * n) = A * m.nodes.row(n).transpose() + c;
  return u;
}

/// Boundary nodes prescribed from the exact field.
fem::ConstrainedDofs boundary_values(const mesh::Mesh& m, const la::Vector& exact)
{
  fem::ConstrainedDofs dofs;
  const auto& nodes = m.node_set("boundary");
  dofs.values.resize(3 * static_cast<long>(nodes.size()));
  for (size_t k = 0; k < nodes.size(); ++k)
    for (int i = 0; i < 3; ++i)
    {
      dofs.dofs.push_back(3 * nodes[k] + i);
      dofs.values(static_cast<long>(3 * k + i)) = exact(3 * nodes[k] + i);
    }
  return dofs;
}

const Eigen::Matrix3d gradient =
    (Eigen::Matrix3d() << 0.1, -0.05, 0.08, 0.03, -0.12, 0.02, 0.07, 0.04, 0.15).finished();
} // namespace

// Reference: a linear displacement field is in the hex8 space, so the FE solution with its
// boundary values reproduces it exactly (round-off), with a constant stress D eps(A).
TEST(Patch, LinearElementReproducesLinearField)
{
  const auto m = test::distorted_patch();
  const fem::Material mat{2e11, 0.3};
  const la::Vector exact = linear_field(m, gradient, Eigen::Vector3d(0.01, -0.02, 0.03));
  fem::Assembler assembler(m, fem::whole_mesh_domain(m), {mat}, fem::Kinematics::linear);
  const la::SparseMatrix K = assembler.stiffness(la::Vector::Zero(exact.size()), fem::StiffnessKind::tangent);
  const fem::DirichletElimination elim(exact.size(), boundary_values(m, exact));
  la::CholmodFactor factor;
  factor.factorize(elim.reduce_matrix(K));
  const la::Vector u = elim.expand(factor.solve(elim.reduce_rhs(K, la::Vector::Zero(exact.size()))));
  EXPECT_LT((u - exact).norm() / exact.norm(), 1e-10);

  Eigen::Matrix<double, 6, 1> eps;
  eps << gradient(0, 0), gradient(1, 1), gradient(2, 2), gradient(0, 1) + gradient(1, 0),
      gradient(1, 2) + gradient(2, 1), gradient(2, 0) + gradient(0, 2);
  const Eigen::Matrix<double, 6, 1> sigma = mat.elasticity_matrix() * eps;
  for (const auto& s : fem::cell_cauchy_stresses(m, u, {mat}, fem::Kinematics::linear))
    EXPECT_LT((s - sigma).norm() / sigma.norm(), 1e-10);
}

// Reference: a homogeneous finite deformation x = (I + A) X is an exact TL equilibrium state
// for any boundary values taken from it (constant S, zero divergence). Newton from u = 0
// must find it at the interior node.
TEST(Patch, TotalLagrangianReproducesHomogeneousDeformation)
{
  const auto m = test::distorted_patch();
  const fem::Material mat{2e11, 0.3};
  const Eigen::Matrix3d A = 2.0 * gradient; // up to 30% strain
  const la::Vector exact = linear_field(m, A, Eigen::Vector3d(0.5, 0.1, -0.2));
  fem::Assembler assembler(m, fem::whole_mesh_domain(m), {mat}, fem::Kinematics::total_lagrangian);

  // Residual at the exact state vanishes at the interior node.
  const la::Vector f_exact = assembler.internal_force(exact);
  const int centre = m.node_set("interior")[0];
  EXPECT_LT(f_exact.segment<3>(3 * centre).norm() / f_exact.norm(), 1e-10);

  const fem::ConstrainedDofs prescribed = boundary_values(m, exact);
  la::Vector u = la::Vector::Zero(exact.size());
  for (size_t k = 0; k < prescribed.dofs.size(); ++k)
    u(prescribed.dofs[k]) = prescribed.values(static_cast<long>(k));
  fem::ConstrainedDofs homogeneous = prescribed;
  homogeneous.values.setZero();
  const fem::DirichletElimination elim(exact.size(), homogeneous);
  for (int it = 0; it < 20; ++it)
  {
    la::SparseMatrix K;
    la::Vector f;
    assembler.assemble(u, fem::StiffnessKind::tangent, &K, &f);
    la::CholmodFactor factor;
    factor.factorize(elim.reduce_matrix(K));
    const la::Vector du = elim.expand(factor.solve(elim.restrict(-f)));
    u += du;
    if (du.norm() < 1e-14 * u.norm())
      break;
  }
  EXPECT_LT((u - exact).norm() / exact.norm(), 1e-10);
}

// Reference: integral of a constant traction over a face set is traction times area, and
// the pressure load acts along the outward normal (here -x on the x = 1 face).
TEST(Loads, TractionAndPressureResultants)
{
  const auto m = test::unit_cube();
  la::Vector f = la::Vector::Zero(24);
  fem::add_face_traction(m, m.face_set("xmax"), Eigen::Vector3d(1, 2, 3), f);
  Eigen::Vector3d total = Eigen::Vector3d::Zero();
  for (int n = 0; n < 8; ++n)
    total += f.segment<3>(3 * n);
  EXPECT_LT((total - Eigen::Vector3d(1, 2, 3)).norm(), 1e-14);
  f.setZero();
  fem::add_face_pressure(m, m.face_set("xmax"), 5.0, f);
  total.setZero();
  for (int n = 0; n < 8; ++n)
    total += f.segment<3>(3 * n);
  EXPECT_LT((total - Eigen::Vector3d(-5, 0, 0)).norm(), 1e-14);
  EXPECT_NEAR(fem::face_set_area(m, m.face_set("xmax")), 1.0, 1e-14);
  // A nodal force is split equally over the set: each of the 4 nodes carries a quarter.
  f.setZero();
  fem::add_nodal_force(m.node_set("xmax"), Eigen::Vector3d(4, -8, 12), f);
  for (int n : m.node_set("xmax"))
    EXPECT_LT((f.segment<3>(3 * n) - Eigen::Vector3d(1, -2, 3)).norm(), 1e-15);
  EXPECT_NEAR(f.sum(), 8.0, 1e-14);
}

// Failure path: conflicting prescribed values on one DOF are reported.
TEST(Dirichlet, ConflictingValuesAreRejected)
{
  const auto m = test::unit_cube();
  std::vector<fem::DirichletCondition> bcs = {{"xmax", {0.0, std::nullopt, std::nullopt}},
                                              {"ymax", {1.0, std::nullopt, std::nullopt}}};
  EXPECT_THROW(fem::collect_dirichlet(m, bcs), feticon::Error);
  bcs[1].value[0] = 0.0;
  EXPECT_EQ(fem::collect_dirichlet(m, bcs).dofs.size(), 6u); // nodes {1,2,5,6} u {2,3,6,7}
  EXPECT_THROW(fem::collect_dirichlet(m, {{"nonexistent", {0.0, 0.0, 0.0}}}), feticon::Error);
}
