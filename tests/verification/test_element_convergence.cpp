/// Convergence of every cell type on a manufactured 3D elasticity solution (issue 38): on the
/// unit cube, u = (1, 2, 3) sin(pi x) sin(pi y) sin(pi z) vanishes on the boundary, and the body
/// force b = -div sigma(u) = -[(lambda + mu) grad(div u) + mu Laplace(u)] makes it the exact
/// solution. Cubes of n^3 cells split into tetrahedra (Kuhn's six per cube) or wedges (two per
/// cube) or kept as hexahedra, assembled from fem::cell_element and solved directly. Reference:
/// the a-priori estimate of the L2 error, O(h^2) for the linear cells and O(h^3) for the
/// quadratic ones (Ciarlet; Brenner & Scott, ch. 5); the rates are measured between the two
/// finest meshes and must be within 0.25 of the theory's.

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

/// A mesh of the unit cube: nodes on the lattice of spacing 1 / (2n), cells by lattice index.
struct CubeMesh
{
  std::vector<Eigen::Vector3d> nodes;
  std::vector<std::vector<int>> cells;
};

CubeMesh cube_mesh(CellKind kind, int n)
{
  const int m = 2 * n + 1;
  std::map<int, int> used; // lattice index -> node
  CubeMesh mesh;
  auto node = [&](int i, int j, int k) {
    const int id = (k * m + j) * m + i;
    auto [it, fresh] = used.emplace(id, static_cast<int>(mesh.nodes.size()));
    if (fresh)
      mesh.nodes.emplace_back(i / (m - 1.0), j / (m - 1.0), k / (m - 1.0));
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
  for (int ck = 0; ck < n; ++ck)
    for (int cj = 0; cj < n; ++cj)
      for (int ci = 0; ci < n; ++ci)
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

/// The L2 norm of u_h - u over the cube for the mesh of n^3 cubes.
double l2_error(CellKind kind, int n)
{
  const CubeMesh mesh = cube_mesh(kind, n);
  const Eigen::Index n_dofs = 3 * static_cast<Eigen::Index>(mesh.nodes.size());
  std::vector<Eigen::Triplet<double>> triplets;
  Eigen::VectorXd load = Eigen::VectorXd::Zero(n_dofs);
  const fem::QuadratureRule& rule = fem::quadrature(kind);
  for (const auto& cell : mesh.cells)
  {
    const Eigen::MatrixX3d X = coordinates(mesh, cell);
    Eigen::VectorXd f;
    Eigen::MatrixXd K;
    fem::cell_element(kind, X, Eigen::MatrixX3d::Zero(X.rows(), 3), material, fem::Kinematics::linear,
                      fem::StiffnessKind::material, fem::Integration::full, f, &K, 0);
    for (size_t a = 0; a < cell.size(); ++a)
      for (size_t b = 0; b < cell.size(); ++b)
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j)
            triplets.emplace_back(3 * cell[a] + i, 3 * cell[b] + j, K(3 * a + i, 3 * b + j));
    for (size_t q = 0; q < rule.points.size(); ++q)
    {
      const Eigen::VectorXd N = fem::shape_values(kind, rule.points[q]);
      const double detJ = (X.transpose() * fem::shape_gradients(kind, rule.points[q])).determinant();
      const Eigen::Vector3d b = body_force(X.transpose() * N);
      for (size_t a = 0; a < cell.size(); ++a)
        load.segment<3>(3 * cell[a]) += N(a) * b * rule.weights[q] * detJ;
    }
  }
  // u = 0 on the boundary: the free DOFs are those of interior nodes.
  std::vector<Eigen::Index> free_of(n_dofs, -1);
  Eigen::Index n_free = 0;
  for (size_t p = 0; p < mesh.nodes.size(); ++p)
    if ((mesh.nodes[p].array() > 1e-12).all() && (mesh.nodes[p].array() < 1 - 1e-12).all())
      for (int i = 0; i < 3; ++i)
        free_of[3 * p + i] = n_free++;
  std::vector<Eigen::Triplet<double>> reduced;
  for (const auto& t : triplets)
    if (free_of[t.row()] >= 0 && free_of[t.col()] >= 0)
      reduced.emplace_back(free_of[t.row()], free_of[t.col()], t.value());
  Eigen::SparseMatrix<double> K(n_free, n_free);
  K.setFromTriplets(reduced.begin(), reduced.end());
  Eigen::VectorXd rhs(n_free);
  for (Eigen::Index d = 0; d < n_dofs; ++d)
    if (free_of[d] >= 0)
      rhs(free_of[d]) = load(d);
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(K);
  EXPECT_EQ(solver.info(), Eigen::Success);
  const Eigen::VectorXd solution = solver.solve(rhs);

  double error = 0;
  const fem::QuadratureRule fine = error_rule(kind);
  for (const auto& cell : mesh.cells)
  {
    const Eigen::MatrixX3d X = coordinates(mesh, cell);
    Eigen::MatrixX3d u = Eigen::MatrixX3d::Zero(X.rows(), 3);
    for (size_t a = 0; a < cell.size(); ++a)
      for (int i = 0; i < 3; ++i)
        if (free_of[3 * cell[a] + i] >= 0)
          u(a, i) = solution(free_of[3 * cell[a] + i]);
    for (size_t q = 0; q < fine.points.size(); ++q)
    {
      const Eigen::VectorXd N = fem::shape_values(kind, fine.points[q]);
      const double detJ = (X.transpose() * fem::shape_gradients(kind, fine.points[q])).determinant();
      error += (u.transpose() * N - exact(X.transpose() * N)).squaredNorm() * fine.weights[q] * detJ;
    }
  }
  return std::sqrt(error);
}

struct ConvergenceCase
{
  CellKind kind;
  std::vector<int> cubes; ///< cubes per side, doubling
  double order;           ///< of the L2 error in h
};

class ElementConvergence : public ::testing::TestWithParam<ConvergenceCase>
{
};

TEST_P(ElementConvergence, L2ErrorFallsAtTheElementsOrder)
{
  const ConvergenceCase& c = GetParam();
  std::vector<double> errors;
  for (int n : c.cubes)
    errors.push_back(l2_error(c.kind, n));
  const double rate = std::log2(errors[errors.size() - 2] / errors.back());
  std::printf("%s: L2 errors", std::string(mesh::cell_type(c.kind).name).c_str());
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
                                           ConvergenceCase{CellKind::hex20, {2, 4, 8}, 3}),
                         [](const auto& info) { return std::string(mesh::cell_type(info.param.kind).name); });
} // namespace
} // namespace feticon
