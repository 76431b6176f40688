#include "fem/body_loads.hpp"

#include "common/error.hpp"
#include "fem/reference_element.hpp"

#include <cmath>

namespace feticon::fem
{
namespace
{
void check_load(const mesh::Mesh& mesh, const std::vector<Material>& materials, const BodyLoad& load)
{
  if (load.kind == BodyLoad::Kind::gravity)
    FETICON_CHECK(load.gravity.allFinite(), load.where << ": the gravity vector is not finite");
  else
  {
    FETICON_CHECK(std::isfinite(load.omega2) && load.omega2 >= 0,
                  load.where << ": omega^2 = " << load.omega2 << " must be finite and not negative");
    FETICON_CHECK(load.point.allFinite() && load.axis.allFinite() && load.axis.norm() > 0,
                  load.where << ": the rotation axis must be a finite point and a non-zero direction");
  }
  for (const int32_t c : load.cells)
    FETICON_CHECK(c >= 0 && static_cast<size_t>(c) < mesh.cells.size(), load.where << ": no cell " << c);
  const auto check_body = [&](size_t c) {
    const int32_t body = mesh.cell_body[c];
    const double rho = materials[body].density;
    FETICON_CHECK(std::isfinite(rho) && rho > 0,
                  load.where << ": body " << mesh.body_names[body]
                             << " has no density (a body load needs *DENSITY, or "
                                "density: in the problem file's bodies)");
  };
  if (load.cells.empty())
    for (size_t c = 0; c < mesh.cells.size(); ++c)
      check_body(c);
  else
    for (const int32_t c : load.cells)
      check_body(static_cast<size_t>(c));
}

/// The force per unit mass at x.
Eigen::Vector3d acceleration(const BodyLoad& load, const Eigen::Vector3d& x)
{
  if (load.kind == BodyLoad::Kind::gravity)
    return load.gravity;
  const Eigen::Vector3d a = load.axis.normalized();
  const Eigen::Vector3d r = x - load.point;
  return load.omega2 * (r - r.dot(a) * a);
}

void add_cell(const mesh::Mesh& mesh, double rho, const BodyLoad& load, size_t c, la::Vector& f)
{
  const mesh::CellKind kind = mesh.cells.kind(c);
  const auto nodes = mesh.cells[c];
  const auto n = static_cast<Eigen::Index>(nodes.size());
  Eigen::MatrixX3d X(n, 3);
  for (Eigen::Index a = 0; a < n; ++a)
    X.row(a) = mesh.nodes.row(nodes[a]);
  const QuadratureRule& rule = quadrature(kind);
  for (size_t q = 0; q < rule.points.size(); ++q)
  {
    const Eigen::VectorXd N = shape_values(kind, rule.points[q]);
    const Eigen::MatrixX3d dN = shape_gradients(kind, rule.points[q]);
    const Eigen::Vector3d x = X.transpose() * N;
    // A 2D cell's volume is its area times the out-of-plane measure (thickness, 2 pi r).
    const double det = mesh::is_planar(kind) ? (X.leftCols<2>().transpose() * dN.leftCols<2>()).determinant() *
            mesh.planar_of_cell(static_cast<int32_t>(c)).measure(x)
                                             : (X.transpose() * dN).determinant();
    const Eigen::Vector3d b = rho * rule.weights[q] * std::abs(det) * acceleration(load, x);
    for (Eigen::Index a = 0; a < n; ++a)
      f.segment<3>(3 * static_cast<la::Index>(nodes[a])) += N[a] * b;
  }
}
} // namespace

void add_body_load(const mesh::Mesh& mesh, const std::vector<Material>& materials, const BodyLoad& load, la::Vector& f)
{
  check_load(mesh, materials, load);
  if (load.cells.empty())
    for (size_t c = 0; c < mesh.cells.size(); ++c)
      add_cell(mesh, materials[mesh.cell_body[c]].density, load, c, f);
  else
    for (const int32_t c : load.cells)
      add_cell(mesh, materials[mesh.cell_body[c]].density, load, static_cast<size_t>(c), f);
}
} // namespace feticon::fem
