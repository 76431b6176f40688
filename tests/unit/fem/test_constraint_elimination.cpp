/// Supports and linear equations eliminated for the direct solves (fem/constraint_elimination.hpp).

#include "fem/assembler.hpp"
#include "fem/constraint_elimination.hpp"
#include "fem/loads.hpp"
#include "la/cholmod.hpp"
#include "mesh/box.hpp"

#include <gtest/gtest.h>

#include <cstdio>

using namespace feticon;

namespace
{
int32_t node_at(const mesh::Mesh& m, double x, double y, double z)
{
  for (int32_t n = 0; n < m.n_nodes(); ++n)
    if ((m.nodes.row(n) - Eigen::RowVector3d(x, y, z)).norm() < 1e-12)
      return n;
  ADD_FAILURE() << "no node at " << x << ", " << y << ", " << z;
  return 0;
}
} // namespace

// Reference: the Lagrange multiplier (KKT) system [K C'; C 0] [u; mu] = [f; d] of the same
// constraints (the supports as unit rows of C, each equation as a row), solved densely by LU:
// an independent route to the constrained minimizer. Equations: three terms with non-unit
// coefficients, one with a term on a support prescribing 1e-4 (moved to the right-hand side),
// and two sharing a DOF, whose elimination substitutes one into the other. The elimination
// gives the same u to round-off (1e-10 relative: the KKT matrix's condition number, about
// 1e8 here, times machine epsilon) and satisfies every constraint.
TEST(ConstraintElimination, MatchesTheLagrangeMultiplierSolve)
{
  mesh::BoxParameters p;
  p.lengths = Eigen::Vector3d(2, 1, 1);
  p.nx = 4;
  p.ny = 2;
  p.nz = 2;
  const mesh::Mesh m = mesh::generate_box(p);
  const int64_t n = 3 * m.n_nodes();
  const fem::Assembler assembler(m, fem::whole_mesh_domain(m), {fem::Material{2e11, 0.3}}, fem::Kinematics::linear);
  const la::SparseMatrix K = assembler.stiffness(la::Vector::Zero(n), fem::StiffnessKind::tangent);
  la::Vector f = la::Vector::Zero(n);
  fem::add_face_traction(m, m.face_set("xmax"), Eigen::Vector3d(1e7, -2e7, 3e7), f);
  const fem::ConstrainedDofs supports = fem::collect_dirichlet(m, {{"xmin", {0.0, 1e-4, 0.0}}});
  const int32_t a = node_at(m, 2, 1, 1), b = node_at(m, 1.5, 0, 0.5), c = node_at(m, 1, 0.5, 0.5);
  const int32_t s = node_at(m, 0, 0.5, 1);
  const std::vector<fem::LinearEquation> equations = {
      {{{a, 0, 2.0}, {b, 1, -0.5}, {c, 2, 1.5}}},
      {{{b, 1, 1.0}, {s, 1, -4.0}}},
      {{{c, 2, 1.0}, {a, 1, 0.25}, {b, 1, -3.0}}},
  };

  const fem::ConstraintElimination elimination(n, supports, equations, &m);
  EXPECT_EQ(elimination.n_free(), n - static_cast<int64_t>(supports.dofs.size()) - 3);
  la::CholmodFactor factor;
  factor.factorize(elimination.reduce_matrix(K));
  const la::Vector u = elimination.expand(factor.solve(elimination.reduce_rhs(K, f)));

  const la::Index n_constraints = static_cast<la::Index>(supports.dofs.size() + equations.size());
  la::Matrix kkt = la::Matrix::Zero(n + n_constraints, n + n_constraints);
  kkt.topLeftCorner(n, n) = la::Matrix(K);
  la::Vector rhs = la::Vector::Zero(n + n_constraints);
  rhs.head(n) = f;
  // Rows scaled by max diag K (ALGORITHMS.md 1, KKT check) for a better conditioned matrix.
  const double scale = K.diagonal().maxCoeff();
  la::Index row = n;
  for (size_t k = 0; k < supports.dofs.size(); ++k, ++row)
  {
    kkt(row, supports.dofs[k]) = kkt(supports.dofs[k], row) = scale;
    rhs(row) = scale * supports.values(static_cast<la::Index>(k));
  }
  for (const auto& equation : equations)
  {
    for (const auto& t : equation.terms)
    {
      kkt(row, 3 * t.node + t.component) += scale * t.coefficient;
      kkt(3 * t.node + t.component, row) += scale * t.coefficient;
    }
    ++row;
  }
  const la::Vector reference = kkt.fullPivLu().solve(rhs).head(n);
  const double error = (u - reference).norm() / reference.norm();
  std::printf("elimination against KKT: |u - u_kkt|/|u_kkt| = %.1e\n", error);
  EXPECT_LT(error, 1e-10);
  const double u_scale = u.cwiseAbs().maxCoeff();
  EXPECT_NEAR(2 * u(3 * a) - 0.5 * u(3 * b + 1) + 1.5 * u(3 * c + 2), 0.0, 1e-14 * u_scale);
  EXPECT_NEAR(u(3 * b + 1) - 4e-4, 0.0, 1e-14 * u_scale);
  EXPECT_NEAR(u(3 * c + 2) + 0.25 * u(3 * a + 1) - 3 * u(3 * b + 1), 0.0, 1e-14 * u_scale);
  for (size_t k = 0; k < supports.dofs.size(); ++k)
    EXPECT_EQ(u(supports.dofs[k]), supports.values(static_cast<la::Index>(k)));

  // impose() makes any u satisfy the constraints, keeping its independent values.
  la::Vector w = la::Vector::Constant(n, 1e-3);
  elimination.impose(w);
  EXPECT_NEAR(2 * w(3 * a) - 0.5 * w(3 * b + 1) + 1.5 * w(3 * c + 2), 0.0, 1e-17);
  EXPECT_EQ(w(supports.dofs[0]), supports.values(0));

  // Without equations: Dirichlet elimination to the bit.
  const fem::ConstraintElimination supports_only(n, supports);
  const fem::DirichletElimination dirichlet(n, supports);
  const la::SparseMatrix A = supports_only.reduce_matrix(K), B = dirichlet.reduce_matrix(K);
  EXPECT_EQ(la::Matrix(A), la::Matrix(B));
  EXPECT_EQ(supports_only.reduce_rhs(K, f), dirichlet.reduce_rhs(K, f));
  EXPECT_EQ(supports_only.reduce_force(f), dirichlet.restrict(f));
}
