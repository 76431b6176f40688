/// Every cell type solving elasticity problems with known answers (issue 38). Convergence on a
/// unit cube, u = (1, 2, 3) sin(pi x) sin(pi y) sin(pi z) vanishes on the boundary, and the body
/// force b = -div sigma(u) = -[(lambda + mu) grad(div u) + mu Laplace(u)] makes it the exact
/// solution. Cubes of n^3 cells split into tetrahedra (Kuhn's six per cube) or wedges (two per
/// cube) or kept as hexahedra, assembled from fem::cell_element and solved directly. Reference:
/// the a-priori estimate of the L2 error, O(h^2) for the linear cells and O(h^3) for the
/// quadratic ones (Ciarlet; Brenner & Scott, ch. 5); the rates are measured between the two
/// finest meshes and must be within 0.25 of the theory's. The total Lagrangian formulation
/// (St Venant-Kirchhoff) the same way: u scaled to |grad u| of up to 0.19 (the Green-Lagrange
/// strain's quadratic part a tenth of its linear part), b = -Div P(u) with P = F S(E(u))
/// differentiated numerically, solved by Newton; the same a-priori orders hold for the smooth
/// nonlinear problem near a stable solution.

#include "fem/cell_element.hpp"

#include <Eigen/Sparse>
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>

namespace feticon
{
namespace
{
using mesh::CellKind;
constexpr double pi = std::numbers::pi;
const fem::Material material{1.0, 0.3};
const Eigen::Vector3d amplitude(1, 2, 3);

Eigen::Vector3d exact(const Eigen::Vector3d& x)
{
  return amplitude * std::sin(pi * x.x()) * std::sin(pi * x.y()) * std::sin(pi * x.z());
}

Eigen::Vector3d body_force(const Eigen::Vector3d& x)
{
  const double lambda = material.lame_lambda(), mu = material.lame_mu();
  const Eigen::Vector3d s(std::sin(pi * x.x()), std::sin(pi * x.y()), std::sin(pi * x.z()));
  const Eigen::Vector3d c(std::cos(pi * x.x()), std::cos(pi * x.y()), std::cos(pi * x.z()));
  Eigen::Matrix3d hessian; // d2 (s_x s_y s_z) / dx_i dx_j
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
    {
      const int k = 3 - i - j;
      hessian(i, j) = i == j ? -pi * pi * s.prod() : pi * pi * c(i) * c(j) * s(k);
    }
  return -((lambda + mu) * hessian * amplitude + mu * (-3 * pi * pi * s.prod()) * amplitude);
}

/// The total Lagrangian problem's solution: the linear one scaled by tl_scale.
constexpr double tl_scale = 0.02;

Eigen::Vector3d exact_total_lagrangian(const Eigen::Vector3d& x) { return tl_scale * exact(x); }

/// First Piola-Kirchhoff stress P = F S of exact_total_lagrangian at x (St Venant-Kirchhoff).
Eigen::Matrix3d first_piola(const Eigen::Vector3d& x)
{
  const Eigen::Vector3d s(std::sin(pi * x.x()), std::sin(pi * x.y()), std::sin(pi * x.z()));
  const Eigen::Vector3d c(std::cos(pi * x.x()), std::cos(pi * x.y()), std::cos(pi * x.z()));
  const Eigen::Vector3d gradient(pi * c.x() * s.y() * s.z(), pi * s.x() * c.y() * s.z(), pi * s.x() * s.y() * c.z());
  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
  const Eigen::Matrix3d F = I + tl_scale * amplitude * gradient.transpose();
  const Eigen::Matrix3d E = 0.5 * (F.transpose() * F - I);
  return F * (material.lame_lambda() * E.trace() * I + 2 * material.lame_mu() * E);
}

/// b = -Div P by central differences: with the step 1e-5 the truncation (about 1e-10 of P) and
/// the round-off (about 1e-11) are far below the finite element errors measured.
Eigen::Vector3d body_force_total_lagrangian(const Eigen::Vector3d& x)
{
  constexpr double h = 1e-5;
  Eigen::Vector3d divergence = Eigen::Vector3d::Zero();
  for (int j = 0; j < 3; ++j)
  {
    const Eigen::Vector3d step = h * Eigen::Vector3d::Unit(j);
    divergence += (first_piola(x + step).col(j) - first_piola(x - step).col(j)) / (2 * h);
  }
  return -divergence;
}

/// A mesh of the box [0, lengths]: nodes on the lattice of half the cell size, cells by lattice
/// index.
struct CubeMesh
{
  std::vector<Eigen::Vector3d> nodes;
  std::vector<std::vector<int>> cells;
};

CubeMesh box_mesh(CellKind kind, const std::array<int, 3>& n, const Eigen::Vector3d& lengths)
{
  std::map<std::array<int, 3>, int> used; // lattice point -> node
  CubeMesh mesh;
  auto node = [&](int i, int j, int k) {
    auto [it, fresh] = used.emplace(std::array<int, 3>{i, j, k}, static_cast<int>(mesh.nodes.size()));
    if (fresh)
      mesh.nodes.emplace_back(lengths.x() * i / (2.0 * n[0]), lengths.y() * j / (2.0 * n[1]),
                              lengths.z() * k / (2.0 * n[2]));
    return it->second;
  };
  const std::array<std::array<int, 3>, 8> corner = {
      {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}}};
  // Kuhn's six tetrahedra about the diagonal 0-6, and two wedges split along 0-2.
  const std::vector<std::vector<int>> tets = {{0, 1, 2, 6}, {0, 2, 3, 6}, {0, 3, 7, 6},
                                              {0, 7, 4, 6}, {0, 4, 5, 6}, {0, 5, 1, 6}};
  const std::vector<std::vector<int>> hexes = {{0, 1, 2, 3, 4, 5, 6, 7}};
  const std::vector<std::vector<int>> wedges = {{0, 1, 2, 4, 5, 6}, {0, 2, 3, 4, 6, 7}};
  const auto& parts = kind == CellKind::tet4 || kind == CellKind::tet10 ? tets
      : kind == CellKind::wedge6                                        ? wedges
                                                                        : hexes;
  const mesh::CellType& type = mesh::cell_type(kind);
  for (int ck = 0; ck < n[2]; ++ck)
    for (int cj = 0; cj < n[1]; ++cj)
      for (int ci = 0; ci < n[0]; ++ci)
        for (const auto& part : parts)
        {
          std::vector<std::array<int, 3>> lattice; // of the cell's corners, then its edge midpoints
          for (int c : part)
            lattice.push_back({2 * (ci + corner[c][0]), 2 * (cj + corner[c][1]), 2 * (ck + corner[c][2])});
          for (const auto& [a, b] : type.edges)
            if (type.order == 2)
              lattice.push_back({(lattice[a][0] + lattice[b][0]) / 2, (lattice[a][1] + lattice[b][1]) / 2,
                                 (lattice[a][2] + lattice[b][2]) / 2});
          std::vector<int> cell;
          for (const auto& p : lattice)
            cell.push_back(node(p[0], p[1], p[2]));
          mesh.cells.push_back(cell);
        }
  return mesh;
}

Eigen::MatrixX3d coordinates(const CubeMesh& mesh, const std::vector<int>& cell)
{
  Eigen::MatrixX3d X(cell.size(), 3);
  for (size_t a = 0; a < cell.size(); ++a)
    X.row(a) = mesh.nodes[cell[a]].transpose();
  return X;
}

/// A rule of high degree on the reference cell for the error integral: Gauss 4^3 on the cube,
/// collapsed (Duffy) onto the tetrahedron and the wedge's triangle.
fem::QuadratureRule error_rule(CellKind kind)
{
  const std::array<double, 4> x = {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563, 0.8611363115940526};
  const std::array<double, 4> w = {0.3478548451374538, 0.6521451548625461, 0.6521451548625461, 0.3478548451374538};
  fem::QuadratureRule rule;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      for (int k = 0; k < 4; ++k)
      {
        const double a = (x[i] + 1) / 2, b = (x[j] + 1) / 2, c = (x[k] + 1) / 2, weight = w[i] * w[j] * w[k];
        if (kind == CellKind::tet4 || kind == CellKind::tet10)
        {
          rule.points.emplace_back(a, b * (1 - a), c * (1 - a) * (1 - b));
          rule.weights.push_back(weight / 8 * (1 - a) * (1 - a) * (1 - b));
        }
        else if (kind == CellKind::wedge6)
        {
          rule.points.emplace_back(a, b * (1 - a), x[k]);
          rule.weights.push_back(weight / 4 * (1 - a));
        }
        else
        {
          rule.points.emplace_back(x[i], x[j], x[k]);
          rule.weights.push_back(weight);
        }
      }
  return rule;
}

/// The displacement on `mesh` under the dead body force `b` (per reference volume), u = 0 at
/// the nodes where `fixed` holds, stiffness integrated by `integration` (loads by the full rule);
/// one row per node. Newton with the consistent tangent from u = 0: the linear problem is solved
/// by its first step; total Lagrangian iterates until the correction is below 1e-12 of u.
template <class BodyForce, class Fixed>
Eigen::MatrixX3d solve(CellKind kind, const CubeMesh& mesh, const fem::Material& material, BodyForce&& b, Fixed&& fixed,
                       fem::Integration integration = fem::Integration::full,
                       fem::Kinematics kinematics = fem::Kinematics::linear)
{
  const Eigen::Index n_dofs = 3 * static_cast<Eigen::Index>(mesh.nodes.size());
  std::vector<Eigen::Index> free_of(n_dofs, -1);
  Eigen::Index n_free = 0;
  for (size_t p = 0; p < mesh.nodes.size(); ++p)
    if (!fixed(mesh.nodes[p]))
      for (int i = 0; i < 3; ++i)
        free_of[3 * p + i] = n_free++;
  Eigen::VectorXd load = Eigen::VectorXd::Zero(n_free);
  const fem::QuadratureRule& rule = fem::quadrature(kind);
  for (const auto& cell : mesh.cells)
  {
    const Eigen::MatrixX3d X = coordinates(mesh, cell);
    for (size_t q = 0; q < rule.points.size(); ++q)
    {
      const Eigen::VectorXd N = fem::shape_values(kind, rule.points[q]);
      const double detJ = (X.transpose() * fem::shape_gradients(kind, rule.points[q])).determinant();
      const Eigen::Vector3d force = b(X.transpose() * N);
      for (size_t a = 0; a < cell.size(); ++a)
        for (int i = 0; i < 3; ++i)
          if (const Eigen::Index d = free_of[3 * cell[a] + i]; d >= 0)
            load(d) += N(a) * force(i) * rule.weights[q] * detJ;
    }
  }
  Eigen::MatrixX3d u = Eigen::MatrixX3d::Zero(static_cast<Eigen::Index>(mesh.nodes.size()), 3);
  for (int iteration = 0; iteration < 30; ++iteration)
  {
    std::vector<Eigen::Triplet<double>> triplets;
    Eigen::VectorXd residual = load;
    for (const auto& cell : mesh.cells)
    {
      const Eigen::MatrixX3d X = coordinates(mesh, cell);
      Eigen::MatrixX3d u_cell(X.rows(), 3);
      for (size_t a = 0; a < cell.size(); ++a)
        u_cell.row(static_cast<Eigen::Index>(a)) = u.row(cell[a]);
      Eigen::VectorXd f;
      Eigen::MatrixXd K;
      fem::cell_element(kind, X, u_cell, material, kinematics, fem::StiffnessKind::tangent, integration, f, &K, 0);
      for (size_t a = 0; a < 3 * cell.size(); ++a)
      {
        const Eigen::Index row = free_of[3 * cell[a / 3] + a % 3];
        if (row < 0)
          continue;
        residual(row) -= f(static_cast<Eigen::Index>(a));
        for (size_t c = 0; c < 3 * cell.size(); ++c)
          if (const Eigen::Index col = free_of[3 * cell[c / 3] + c % 3]; col >= 0)
            triplets.emplace_back(row, col, K(static_cast<Eigen::Index>(a), static_cast<Eigen::Index>(c)));
      }
    }
    Eigen::SparseMatrix<double> K(n_free, n_free);
    K.setFromTriplets(triplets.begin(), triplets.end());
    const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(K);
    EXPECT_EQ(solver.info(), Eigen::Success);
    const Eigen::VectorXd du = solver.solve(residual);
    for (Eigen::Index d = 0; d < n_dofs; ++d)
      if (free_of[d] >= 0)
        u(d / 3, d % 3) += du(free_of[d]);
    if (kinematics == fem::Kinematics::linear || du.norm() <= 1e-12 * u.norm())
      return u;
  }
  ADD_FAILURE() << "Newton did not converge in 30 iterations";
  return u;
}

/// The L2 norm of u_h - u over the cube for the mesh of n^3 cubes (the linear problem, or the
/// total Lagrangian one).
double l2_error(CellKind kind, int n, fem::Integration integration, fem::Kinematics kinematics)
{
  const bool linear = kinematics == fem::Kinematics::linear;
  const CubeMesh mesh = box_mesh(kind, {n, n, n}, Eigen::Vector3d::Ones());
  // u = 0 on the boundary.
  const Eigen::MatrixX3d solution = solve(
      kind, mesh, material, linear ? body_force : body_force_total_lagrangian,
      [](const Eigen::Vector3d& x) { return (x.array() < 1e-12).any() || (x.array() > 1 - 1e-12).any(); }, integration,
      kinematics);
  const auto u_exact = linear ? exact : exact_total_lagrangian;
  double error = 0;
  const fem::QuadratureRule fine = error_rule(kind);
  for (const auto& cell : mesh.cells)
  {
    const Eigen::MatrixX3d X = coordinates(mesh, cell);
    Eigen::MatrixX3d u(X.rows(), 3);
    for (size_t a = 0; a < cell.size(); ++a)
      u.row(a) = solution.row(cell[a]);
    for (size_t q = 0; q < fine.points.size(); ++q)
    {
      const Eigen::VectorXd N = fem::shape_values(kind, fine.points[q]);
      const double detJ = (X.transpose() * fem::shape_gradients(kind, fine.points[q])).determinant();
      error += (u.transpose() * N - u_exact(X.transpose() * N)).squaredNorm() * fine.weights[q] * detJ;
    }
  }
  return std::sqrt(error);
}

struct ConvergenceCase
{
  CellKind kind;
  std::vector<int> cubes; ///< cubes per side, doubling
  double order;           ///< of the L2 error in h
  fem::Integration integration = fem::Integration::full;
  fem::Kinematics kinematics = fem::Kinematics::linear;
};

class ElementConvergence : public ::testing::TestWithParam<ConvergenceCase>
{
};

TEST_P(ElementConvergence, L2ErrorFallsAtTheElementsOrder)
{
  const ConvergenceCase& c = GetParam();
  std::vector<double> errors;
  for (int n : c.cubes)
    errors.push_back(l2_error(c.kind, n, c.integration, c.kinematics));
  const double rate = std::log2(errors[errors.size() - 2] / errors.back());
  std::printf("%s%s: L2 errors", std::string(mesh::cell_type(c.kind).name).c_str(),
              c.kinematics == fem::Kinematics::linear ? "" : " (total Lagrangian)");
  for (size_t k = 0; k < errors.size(); ++k)
    std::printf(" %.3e (n = %d)", errors[k], c.cubes[k]);
  std::printf(", rate %.2f (theory %.0f)\n", rate, c.order);
  EXPECT_NEAR(rate, c.order, 0.25);
}

INSTANTIATE_TEST_SUITE_P(AllTypes, ElementConvergence,
                         ::testing::Values(ConvergenceCase{CellKind::hex8, {4, 8, 16}, 2},
                                           ConvergenceCase{CellKind::tet4, {4, 8, 16}, 2},
                                           ConvergenceCase{CellKind::wedge6, {4, 8, 16}, 2},
                                           ConvergenceCase{CellKind::tet10, {2, 4, 8}, 3},
                                           ConvergenceCase{CellKind::hex20, {2, 4, 8}, 3},
                                           // C3D20R: 2x2x2 points keep the order (Zienkiewicz & Taylor,
                                           // vol. 1, ch. 9: the reduced rule still integrates the
                                           // complete quadratic's energy exactly)
                                           ConvergenceCase{CellKind::hex20, {2, 4, 8}, 3, fem::Integration::reduced}),
                         [](const auto& info) {
  return std::string(mesh::cell_type(info.param.kind).name) +
      (info.param.integration == fem::Integration::reduced ? "_reduced" : "");
});

// The two coarser meshes of each linear case suffice for the rate (linear: hex8 1.97, tet10
// 3.04 between them), and keep the Newton solves short.
INSTANTIATE_TEST_SUITE_P(
    TotalLagrangian, ElementConvergence,
    ::testing::Values(
        ConvergenceCase{CellKind::hex8, {4, 8}, 2, fem::Integration::full, fem::Kinematics::total_lagrangian},
        ConvergenceCase{CellKind::tet4, {4, 8}, 2, fem::Integration::full, fem::Kinematics::total_lagrangian},
        ConvergenceCase{CellKind::wedge6, {4, 8}, 2, fem::Integration::full, fem::Kinematics::total_lagrangian},
        ConvergenceCase{CellKind::tet10, {2, 4}, 3, fem::Integration::full, fem::Kinematics::total_lagrangian},
        ConvergenceCase{CellKind::hex20, {2, 4}, 3, fem::Integration::full, fem::Kinematics::total_lagrangian},
        ConvergenceCase{CellKind::hex20, {2, 4}, 3, fem::Integration::reduced, fem::Kinematics::total_lagrangian}),
    [](const auto& info) {
  return std::string(mesh::cell_type(info.param.kind).name) +
      (info.param.integration == fem::Integration::reduced ? "_reduced" : "");
    });
} // namespace
} // namespace feticon

namespace feticon
{
namespace
{
/// A cantilever 10 x 1 x 1 clamped at x = 0 (every node there fixed) under its own weight q
/// per volume, 10 x 2 x 2 cubes (`refinement` times as many along each side). References:
/// Timoshenko's beam, tip deflection w L^4 / (8 E I) + w L^2 / (2 kappa G A) with w = q A and
/// Cowper's kappa = 10 (1 + nu) / (12 + 11 nu) for the rectangle, and the 3D solution of hex20
/// on the mesh refined three times, which the clamp (its Poisson contraction held) makes
/// stiffer than the beam by about a percent (measured 0.989). On the coarse mesh the quadratic
/// cells come within 2 % of the fine solution (measured: tet10 1.2 %, hex20 0.9 % below) while
/// the linear tetrahedron locks (0.35 of the beam: its constant strain cannot bend) and the
/// fully integrated hexahedron and wedge lock in shear (0.69) (Zienkiewicz & Taylor, vol. 1,
/// ch. 11).
double tip_deflection_over_beam_theory(CellKind kind, int refinement = 1,
                                       fem::Integration integration = fem::Integration::full)
{
  const Eigen::Vector3d lengths(10, 1, 1);
  const CubeMesh mesh = box_mesh(kind, {10 * refinement, 2 * refinement, 2 * refinement}, lengths);
  const double q = 1e-3;
  const Eigen::MatrixX3d u = solve(
      kind, mesh, material, [q](const Eigen::Vector3d&) { return Eigen::Vector3d(0, 0, -q); },
      [](const Eigen::Vector3d& x) { return x.x() < 1e-12; }, integration);
  double tip = 0;
  for (size_t p = 0; p < mesh.nodes.size(); ++p)
    if ((mesh.nodes[p] - Eigen::Vector3d(10, 0.5, 0.5)).norm() < 1e-12)
      tip = -u(static_cast<Eigen::Index>(p), 2);
  const double area = 1, inertia = 1.0 / 12, nu = material.poisson;
  const double kappa = 10 * (1 + nu) / (12 + 11 * nu), w = q * area, L = lengths.x();
  const double beam =
      w * std::pow(L, 4) / (8 * material.young * inertia) + w * L * L / (2 * kappa * material.lame_mu() * area);
  return tip / beam;
}

TEST(ElementCantilever, QuadraticCellsMeetTheFineSolutionAndLinearTetrahedraLock)
{
  const double fine = tip_deflection_over_beam_theory(CellKind::hex20, 3);
  std::printf("cantilever hex20 refined 3x: tip deflection / Timoshenko %.4f\n", fine);
  EXPECT_NEAR(fine, 1.0, 0.03) << "the 3D clamp against the beam";
  std::map<CellKind, double> ratio;
  for (const CellKind kind : mesh::solid_cell_kinds)
  {
    ratio[kind] = tip_deflection_over_beam_theory(kind);
    std::printf("cantilever %s: tip deflection / Timoshenko %.4f\n", std::string(mesh::cell_type(kind).name).c_str(),
                ratio[kind]);
  }
  // C3D20R: reduced integration softens the cell towards the fine solution.
  const double reduced = tip_deflection_over_beam_theory(CellKind::hex20, 1, fem::Integration::reduced);
  std::printf("cantilever hex20 reduced (C3D20R): tip deflection / Timoshenko %.4f\n", reduced);
  EXPECT_NEAR(ratio[CellKind::tet10] / fine, 1.0, 0.02);
  EXPECT_NEAR(ratio[CellKind::hex20] / fine, 1.0, 0.02);
  EXPECT_NEAR(reduced / fine, 1.0, 0.01);
  EXPECT_GT(reduced, ratio[CellKind::hex20]);
  EXPECT_LT(ratio[CellKind::tet4], 0.5) << "tet4 locks with two cells through the depth";
  EXPECT_LT(ratio[CellKind::hex8], 0.8) << "hex8 with full integration locks in shear";
}
} // namespace
} // namespace feticon
