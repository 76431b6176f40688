/// Equality rows of linear equations (*EQUATION) in Total FETI: orthonormal together with the
/// gluing and Dirichlet rows, the same constraints as the equations, and the degenerate
/// equations refused with a message naming them (decomposition/constraint_rows.hpp).

#include "common/error.hpp"
#include "decomposition/constraint_rows.hpp"
#include "fem/constraint_elimination.hpp"
#include "mesh/box.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <functional>
#include <random>

using namespace feticon;

namespace
{
/// [0,2]x[0,1]x[0,1], 4x2x2 cells: split 2x2x2, its centre node (1, 0.5, 0.5) has 8 copies.
mesh::Mesh box()
{
  mesh::BoxParameters p;
  p.lengths = Eigen::Vector3d(2, 1, 1);
  p.nx = 4;
  p.ny = 2;
  p.nz = 2;
  return mesh::generate_box(p);
}

int32_t node_at(const mesh::Mesh& m, double x, double y, double z)
{
  for (int32_t n = 0; n < m.n_nodes(); ++n)
    if ((m.nodes.row(n) - Eigen::RowVector3d(x, y, z)).norm() < 1e-12)
      return n;
  ADD_FAILURE() << "no node at " << x << ", " << y << ", " << z;
  return 0;
}

/// The rows as a dense matrix over the stacked DOFs (one rank).
la::Matrix dense_rows(const decomposition::Decomposition& decomp, const decomposition::ConstraintRows& rows)
{
  la::Matrix B = la::Matrix::Zero(rows.n_rows(), decomp.n_primal());
  for (int64_t r = 0; r < rows.n_rows(); ++r)
    for (const auto& e : rows.row(r))
      B(r, decomp.offset(e.subdomain) + e.dof) += e.value;
  return B;
}

/// The message of the feticon::Error `f` throws ("" and a test failure if it throws none).
std::string error_of(const std::function<void()>& f)
{
  try
  {
    f();
  }
  catch (const Error& e)
  {
    return e.what();
  }
  ADD_FAILURE() << "no feticon::Error thrown";
  return "";
}
} // namespace

// Reference: B_E B_E' = I (ALGORITHMS.md 3) must hold with the equation rows too, which the
// (B B')^-1 scaling of the preconditioner assumes (dual/constraint_scaling.hpp); a displacement
// that satisfies the supports and the equations (from the independent elimination of
// fem::ConstraintElimination, copied to every subdomain) satisfies every row, and one that
// violates one equation violates only the rows of that equation's group. Three equations: two
// sharing a DOF (orthonormalized together), one on a node with 8 copies, one with a term on a
// support prescribing 0.002 (moved to c) and one with a repeated term (summed).
TEST(EquationRows, OrthonormalAndTheSameConstraintsAsTheEquations)
{
  const mesh::Mesh m = box();
  const decomposition::Decomposition decomp(m, decomposition::partition_structured(m, {2, 2, 2}));
  const int32_t centre = node_at(m, 1, 0.5, 0.5), corner = node_at(m, 2, 1, 1);
  const int32_t bottom = node_at(m, 0.5, 0, 0), support = node_at(m, 0, 0.5, 0.5);
  const int32_t side = node_at(m, 1.5, 1, 0.5), far = node_at(m, 2, 0, 0);
  ASSERT_EQ(decomp.copies(centre).size(), 8u);
  const fem::ConstrainedDofs dirichlet = fem::collect_dirichlet(m, {{"xmin", {0.0, 0.0, 0.002}}});
  const std::vector<fem::LinearEquation> equations = {
      {{{centre, 0, 1.0}, {corner, 0, -1.0}}},
      {{{corner, 0, 2.0}, {bottom, 2, -3.0}, {support, 2, 0.5}}},
      {{{side, 1, 1.0}, {side, 1, 1.0}, {far, 2, -1.0}}},
  };
  const auto eq = decomposition::build_equality_rows(decomp, dirichlet, equations);
  const auto plain = decomposition::build_equality_rows(decomp, dirichlet);
  ASSERT_EQ(eq.n_equations, 3);
  EXPECT_EQ(eq.n_gluing, plain.n_gluing);
  EXPECT_EQ(eq.n_dirichlet, plain.n_dirichlet);
  ASSERT_EQ(eq.rows.n_rows(), plain.rows.n_rows() + 3);
  const int64_t first = eq.n_gluing + eq.n_dirichlet;
  for (int64_t k = 0; k < 3; ++k)
    EXPECT_EQ(eq.rows.id(plain.rows.n_rows() + k), first + k);
  // The first equation's row: the centre's coefficient split over its 8 copies, the corner's
  // on its one copy (before orthonormalization with the second equation, which it precedes).
  EXPECT_EQ(eq.rows.row(plain.rows.n_rows()).size(), 9u);

  const la::Matrix B = dense_rows(decomp, eq.rows);
  const double orthonormality = (B * B.transpose() - la::Matrix::Identity(B.rows(), B.rows())).norm();
  std::printf("||B_E B_E' - I|| = %.1e with %ld equality rows\n", orthonormality, static_cast<long>(B.rows()));
  EXPECT_LT(orthonormality, 1e-13);

  const int64_t n = 3 * m.n_nodes();
  const fem::ConstraintElimination elimination(n, dirichlet, equations, &m);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> uniform(-1e-3, 1e-3);
  la::Vector v(elimination.n_free());
  for (la::Index i = 0; i < v.size(); ++i)
    v(i) = uniform(random);
  la::Vector u = elimination.expand(v);
  EXPECT_NEAR(u(3 * centre) - u(3 * corner), 0.0, 1e-18);
  EXPECT_NEAR(2 * u(3 * corner) - 3 * u(3 * bottom + 2) + 0.5 * 0.002, 0.0, 1e-18);
  const la::Vector c = eq.rows.c_vector();
  EXPECT_LT((B * decomp.scatter_copy(u) - c).cwiseAbs().maxCoeff(), 1e-16);

  u(3 * side + 1) += 1e-3; // violates the third equation only
  const la::Vector residual = B * decomp.scatter_copy(u) - c;
  EXPECT_LT(residual.head(plain.rows.n_rows() + 2).cwiseAbs().maxCoeff(), 1e-16);
  // Its row is (2 u_y(side) - u_z(far)) / sqrt(3), the norm of the split row being
  // sqrt(2^2 / 2 + 1^2): side has 2 copies (z = 0.5 is an interface), far 1.
  ASSERT_EQ(decomp.copies(side).size(), 2u);
  EXPECT_NEAR(residual(plain.rows.n_rows() + 2), 2e-3 / std::sqrt(3.0), 1e-15);
}

// Reference: the equations below have no free term, or are combinations of the supports and
// the equations before them; each must be refused with a one-line message naming it.
TEST(EquationRows, DegenerateEquationsAreNamed)
{
  const mesh::Mesh m = box();
  const decomposition::Decomposition decomp(m, decomposition::partition_structured(m, {2, 1, 1}));
  const fem::ConstrainedDofs clamp = fem::collect_dirichlet(m, {{"xmin", {0.0, 0.0, 0.0}}});
  const int32_t a = node_at(m, 1, 0.5, 0.5), b = node_at(m, 2, 1, 1), c = node_at(m, 1.5, 0, 0);
  const int32_t s = node_at(m, 0, 0.5, 0.5), t = node_at(m, 0, 0, 0);
  const auto build = [&](const decomposition::Decomposition& d, const std::vector<fem::LinearEquation>& equations) {
    return [&d, &clamp, equations] { decomposition::build_equality_rows(d, clamp, equations); };
  };

  // Every term on a support: repeats the clamp.
  std::string message = error_of(build(decomp, {{{{s, 0, 1.0}, {t, 1, -2.0}}}}));
  EXPECT_NE(message.find("linear equation 1 of 1"), std::string::npos) << message;
  EXPECT_NE(message.find("no term on a free degree of freedom"), std::string::npos) << message;
  // A single term on a supported DOF (an *EQUATION on a DOF that *BOUNDARY also fixes).
  message = error_of(build(decomp, {{{{a, 0, 1.0}, {b, 0, -1.0}}}, {{{s, 2, 1.0}}}}));
  EXPECT_NE(message.find("linear equation 2 of 2"), std::string::npos) << message;
  // Terms that cancel.
  message = error_of(build(decomp, {{{{a, 1, 1.0}, {a, 1, -1.0}}}}));
  EXPECT_NE(message.find("linear equation 1 of 1"), std::string::npos) << message;
  // The same equation twice, scaled.
  message = error_of(build(decomp, {{{{a, 0, 1.0}, {b, 0, -1.0}}}, {{{a, 0, -2.5}, {b, 0, 2.5}}}}));
  EXPECT_NE(message.find("linear equation 2 of 2"), std::string::npos) << message;
  EXPECT_NE(message.find("linearly dependent"), std::string::npos) << message;
  std::printf("%s\n", message.c_str());
  // A chain closing on itself: the third is the sum of the first two.
  message = error_of(
      build(decomp, {{{{a, 0, 1.0}, {b, 0, -1.0}}}, {{{b, 0, 1.0}, {c, 0, -1.0}}}, {{{a, 0, 1.0}, {c, 0, -1.0}}}}));
  EXPECT_NE(message.find("linear equation 3 of 3"), std::string::npos) << message;
  EXPECT_NE(message.find("linearly dependent"), std::string::npos) << message;
  // Dependent through a support: u_x(a) = u_x(s) = 0 already says u_x(a) = 0.
  message = error_of(build(decomp, {{{{a, 0, 1.0}, {s, 0, -1.0}}}, {{{a, 0, 3.0}}}}));
  EXPECT_NE(message.find("linear equation 2 of 2"), std::string::npos) << message;
  EXPECT_NE(message.find("linearly dependent"), std::string::npos) << message;
  // Plane strain: u_z is eliminated, so an equation on u_z alone says nothing.
  const decomposition::Decomposition plane(m, decomposition::partition_structured(m, {2, 1, 1}), {false, false, true});
  message = error_of(build(plane, {{{{a, 2, 1.0}, {b, 2, -1.0}}}}));
  EXPECT_NE(message.find("linear equation 1 of 1"), std::string::npos) << message;
  EXPECT_NE(message.find("eliminated"), std::string::npos) << message;
  // ... but a term on u_z beside free ones is dropped.
  const auto rows = decomposition::build_equality_rows(plane, clamp, {{{{a, 2, 1.0}, {b, 0, -1.0}}}});
  EXPECT_EQ(rows.n_equations, 1);
  // The elimination of the undecomposed solves refuses the same equations.
  const int64_t n = 3 * m.n_nodes();
  message = error_of([&] {
    fem::ConstraintElimination(n, clamp, {{{{a, 0, 1.0}, {b, 0, -1.0}}}, {{{a, 0, -2.5}, {b, 0, 2.5}}}}, &m);
  });
  EXPECT_NE(message.find("linear equation 2 of 2"), std::string::npos) << message;
  message = error_of([&] {
    fem::ConstraintElimination(n, clamp, {{{{a, 0, 1.0}, {s, 0, -1.0}}}, {{{a, 0, 3.0}}}}, &m);
  });
  EXPECT_NE(message.find("linear equation 2 of 2"), std::string::npos) << message;
  message = error_of([&] { fem::ConstraintElimination(n, clamp, {{{{s, 0, 1.0}}}}, &m); });
  EXPECT_NE(message.find("no term on a free degree of freedom"), std::string::npos) << message;
}
