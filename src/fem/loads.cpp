#include "fem/loads.hpp"

#include "common/error.hpp"
#include "fem/reference_face.hpp"

#include <cmath>

namespace feticon::fem
{
namespace
{
/// Calls visit(N (the face's shape values), dA, unit normal) at the quadrature points of a face.
/// quad4 keeps its own loop: the arithmetic of hex8 runs before faces had types.
template <class Visit>
void integrate_face(const mesh::Mesh& mesh, const mesh::Face& face, Visit&& visit)
{
  if (face.kind != mesh::FaceKind::quad4)
  {
    const FaceQuadrature& rule = face_quadrature(face.kind);
    for (size_t q = 0; q < rule.points.size(); ++q)
    {
      const Eigen::VectorXd N = face_shape_values(face.kind, rule.points[q]);
      const Eigen::MatrixX2d dN = face_shape_gradients(face.kind, rule.points[q]);
      Eigen::Vector3d dxi = Eigen::Vector3d::Zero(), deta = Eigen::Vector3d::Zero(), x = Eigen::Vector3d::Zero();
      for (int a = 0; a < face.size(); ++a)
      {
        dxi += dN(a, 0) * mesh.nodes.row(face[a]).transpose();
        deta += dN(a, 1) * mesh.nodes.row(face[a]).transpose();
        x += N(a) * mesh.nodes.row(face[a]).transpose();
      }
      // The edge of a 2D cell is swept through the out-of-plane measure (thickness, 2 pi r):
      // x_,eta = measure e_z, so dA = |x_,xi| measure and the normal x_,xi x e_z is outward.
      if (mesh::is_line(face.kind))
        deta = mesh.planar_of_node(face[0]).measure(x) * Eigen::Vector3d::UnitZ();
      const Eigen::Vector3d normal = dxi.cross(deta);
      const double dA = normal.norm();
      FETICON_CHECK(dA > 0,
                    "degenerate boundary face (" << face.size() << " nodes) with corner nodes " << face[0] << ", "
                                                 << face[1] << ", ...");
      visit(N, rule.weights[q] * dA, normal / dA);
    }
    return;
  }
  static const double g = 1.0 / std::sqrt(3.0);
  static const double xi_a[4] = {-1, 1, 1, -1}, eta_a[4] = {-1, -1, 1, 1};
  for (double xi : {-g, g})
    for (double eta : {-g, g})
    {
      Eigen::Vector4d N;
      Eigen::Vector3d dxi = Eigen::Vector3d::Zero(), deta = Eigen::Vector3d::Zero();
      for (int a = 0; a < 4; ++a)
      {
        N(a) = 0.25 * (1 + xi_a[a] * xi) * (1 + eta_a[a] * eta);
        const Eigen::Vector3d x = mesh.nodes.row(face[a]).transpose();
        dxi += 0.25 * xi_a[a] * (1 + eta_a[a] * eta) * x;
        deta += 0.25 * eta_a[a] * (1 + xi_a[a] * xi) * x;
      }
      // Face nodes run counter-clockwise seen from outside, so dxi x deta points outward.
      const Eigen::Vector3d normal = dxi.cross(deta);
      const double dA = normal.norm();
      FETICON_CHECK(dA > 0,
                    "degenerate boundary face with nodes " << face[0] << ", " << face[1] << ", " << face[2] << ", "
                                                           << face[3]);
      visit(Eigen::VectorXd(N), dA, normal / dA);
    }
}
} // namespace

void add_face_traction(const mesh::Mesh& mesh, const std::vector<mesh::Face>& faces, const Eigen::Vector3d& traction,
                       la::Vector& f)
{
  FETICON_ASSERT(f.size() == 3 * mesh.n_nodes(), "force vector size");
  for (const mesh::Face& face : faces)
    integrate_face(mesh, face, [&](const Eigen::VectorXd& N, double dA, const Eigen::Vector3d&) {
      for (int a = 0; a < face.size(); ++a)
        f.segment<3>(3 * face[a]) += N(a) * dA * traction;
    });
}

void add_face_pressure(const mesh::Mesh& mesh, const std::vector<mesh::Face>& faces, double pressure, la::Vector& f)
{
  FETICON_ASSERT(f.size() == 3 * mesh.n_nodes(), "force vector size");
  for (const mesh::Face& face : faces)
    integrate_face(mesh, face, [&](const Eigen::VectorXd& N, double dA, const Eigen::Vector3d& normal) {
      for (int a = 0; a < face.size(); ++a)
        f.segment<3>(3 * face[a]) -= N(a) * dA * pressure * normal;
    });
}

void add_nodal_force(const std::vector<int32_t>& nodes, const Eigen::Vector3d& total_force, la::Vector& f)
{
  FETICON_CHECK(!nodes.empty(), "a nodal force was applied to an empty node set");
  for (int32_t n : nodes)
    f.segment<3>(3 * n) += total_force / static_cast<double>(nodes.size());
}

double face_set_area(const mesh::Mesh& mesh, const std::vector<mesh::Face>& faces)
{
  double area = 0;
  for (const mesh::Face& face : faces)
    integrate_face(mesh, face, [&](const Eigen::VectorXd&, double dA, const Eigen::Vector3d&) { area += dA; });
  return area;
}
} // namespace feticon::fem
