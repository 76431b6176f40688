/// Tests of the dual mortar integrals on faces of every type (contact/mortar_face_integration.hpp).
/// References: the definitions (partition of unity, biorthogonality), the closed-form nodal
/// integrals of the transformed quadratic functions on a flat face (2A/15 and 3A/15 for tri6,
/// A/20 and 3A/15 for quad8, from int N dA = 0, A/3 and -A/12, A/3), and, for a slave face
/// against a master face on the same nodes, sum_a M_ja x_a = D~_j x~_j with the transformed
/// nodal values x~_c = x_c, x~_m = (x_m - alpha (x_c1 + x_c2)) / (1 - 2 alpha), which holds
/// because sum_a N_a x_a = sum_k N~_k x~_k is the same point and Phi_j is biorthogonal to N~.

#include "contact/mortar_face_integration.hpp"

#include "fem/reference_face.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>

namespace feticon::contact
{
namespace
{
using mesh::FaceKind;

/// A flat face of the given type in the plane z = 0.3 tilted about x, its nodes at the
/// reference coordinates times a shear and a scale (area known), normal along +z' (outward up).
FaceGeometry flat_face(FaceKind kind, double* area = nullptr)
{
  Eigen::Matrix2d shape;
  shape << 0.7, 0.2, 0.0, 0.5; // det 0.35
  const double tilt = 0.3;
  FaceGeometry face;
  face.kind = kind;
  face.x.resize(mesh::face_nodes(kind), 3);
  for (int a = 0; a < mesh::face_nodes(kind); ++a)
  {
    const Eigen::Vector2d p = shape * face_node_xi(kind, a);
    face.x.row(a) << p(0), std::cos(tilt) * p(1), 0.3 + std::sin(tilt) * p(1);
  }
  if (area)
    *area = 0.35 * (mesh::face_corners(kind) == 3 ? 0.5 : 4.0);
  return face;
}

/// The same face seen from the other body: its corners in reverse order (and its edge nodes
/// with them), so that its normal points the other way.
FaceGeometry reversed(const FaceGeometry& face)
{
  const int corners = mesh::face_corners(face.kind);
  FaceGeometry out = face;
  for (int k = 0; k < corners; ++k)
    out.x.row(k) = face.x.row((corners - k) % corners);
  // Edge k of the reversed face joins old corners (corners - k) % corners and corners - k - 1.
  for (int e = 0; e < corners && face.x.rows() > corners; ++e)
    out.x.row(corners + e) = face.x.row(corners + (corners - 1 - e));
  return out;
}

class MortarFaces : public ::testing::TestWithParam<FaceKind>
{
};

TEST_P(MortarFaces, TransformedFunctionsSumToOneAndHavePositiveIntegrals)
{
  const FaceKind kind = GetParam();
  for (const Eigen::Vector2d& xi : {Eigen::Vector2d(0.1, 0.2), Eigen::Vector2d(0.3, 0.05)})
    EXPECT_NEAR(transformed_shape_values(kind, xi).sum(), 1.0, 1e-14);
  double area = 0;
  const FaceDualBasis dual = face_dual_basis(flat_face(kind, &area));
  const int corners = mesh::face_corners(kind);
  const double alpha = quadratic_dual_alpha;
  for (int j = 0; j < mesh::face_nodes(kind); ++j)
  {
    double expected = area / corners; // tri3, quad4: int N_j dA
    if (kind == FaceKind::tri6)
      expected = j < corners ? 2 * alpha * area / 3 : (1 - 2 * alpha) * area / 3;
    if (kind == FaceKind::quad8)
      expected = j < corners ? (2 * alpha / 3 - 1.0 / 12) * area : (1 - 2 * alpha) * area / 3;
    EXPECT_NEAR(dual.nodal_area(j), expected, 1e-13 * area) << "node " << j;
    EXPECT_GT(dual.nodal_area(j), 0) << "node " << j;
  }
}

TEST_P(MortarFaces, DualFunctionsAreBiorthogonalToTheTransformedOnes)
{
  const FaceKind kind = GetParam();
  const FaceGeometry face = flat_face(kind);
  const FaceDualBasis dual = face_dual_basis(face);
  const int n = mesh::face_nodes(kind);
  Eigen::MatrixXd product = Eigen::MatrixXd::Zero(n, n);
  // Phi N~ is of degree 4 on quadratic faces: rules of degree 10 and 9 per direction.
  const bool tri = mesh::face_corners(kind) == 3;
  const QuadratureRule2d fine = tri ? gauss_triangle(6) : gauss_square(5);
  for (size_t q = 0; q < fine.points.size(); ++q)
  {
    const Eigen::VectorXd N = transformed_shape_values(kind, fine.points[q]);
    const Eigen::Matrix<double, 3, 2> t = face.x.transpose() * fem::face_shape_gradients(kind, fine.points[q]);
    const double w = (tri ? 0.5 : 1.0) * fine.weights[q] * t.col(0).cross(t.col(1)).norm();
    product += w * (dual.coefficients * N) * N.transpose();
  }
  const Eigen::MatrixXd expected = dual.nodal_area.asDiagonal();
  EXPECT_LT((product - expected).cwiseAbs().maxCoeff(), 1e-13 * dual.nodal_area.sum());
}

TEST_P(MortarFaces, CouplingWithTheSameFaceGivesTheTransformedNodalValues)
{
  const FaceKind kind = GetParam();
  const FaceGeometry slave = flat_face(kind);
  const FaceGeometry master = reversed(slave);
  const FaceDualBasis dual = face_dual_basis(slave);
  const std::optional<Eigen::MatrixXd> M = integrate_face_segment(slave, dual, master);
  ASSERT_TRUE(M.has_value());
  const int corners = mesh::face_corners(kind);
  const double alpha = quadratic_dual_alpha;
  for (int j = 0; j < mesh::face_nodes(kind); ++j)
  {
    Eigen::Vector3d transformed = slave.x.row(j).transpose();
    if (j >= corners)
    {
      const int e = j - corners;
      transformed =
          (transformed - alpha * (slave.x.row(e) + slave.x.row((e + 1) % corners)).transpose()) / (1 - 2 * alpha);
    }
    const Eigen::Vector3d weighted = master.x.transpose() * M->row(j).transpose();
    EXPECT_NEAR(M->row(j).sum(), dual.nodal_area(j), 1e-13) << "node " << j;
    EXPECT_LT((weighted - dual.nodal_area(j) * transformed).norm(), 1e-13) << "node " << j;
  }
}

TEST(MortarFaces, FacesApartDoNotCouple)
{
  const FaceGeometry slave = flat_face(FaceKind::tri6);
  FaceGeometry master = reversed(slave);
  master.x.col(0).array() += 10.0;
  EXPECT_FALSE(integrate_face_segment(slave, face_dual_basis(slave), master).has_value());
}

// SlaveFootprint only sorts out masters the segment routines would not integrate: the master
// face slid across the slave in its plane, in steps of 0.2, couples
// (integrate_face_segment, and mortar_integration.hpp's integrate_segment for quad4) only where
// the footprint keeps it, and the footprint drops it once it lies wholly beside the slave
// (the faces span at most 1.8 along x; the shifts reach 3).
TEST_P(MortarFaces, FootprintKeepsEveryMasterThatCouples)
{
  const FaceKind kind = GetParam();
  const FaceGeometry slave = flat_face(kind);
  const SlaveFootprint footprint(slave);
  const FaceDualBasis dual = face_dual_basis(slave);
  const Eigen::Vector3d along(1.0, 0.0, 0.0); // in the face's tilted plane
  int coupled = 0, dropped = 0;
  for (int step = -15; step <= 15; ++step)
  {
    FaceGeometry master = reversed(slave);
    master.x.rowwise() += (0.2 * step * along).transpose();
    const bool couples = integrate_face_segment(slave, dual, master).has_value();
    const bool quad_couples =
        kind == FaceKind::quad4 && integrate_segment(slave.quad(), dual_basis(slave.quad()), master.quad()).has_value();
    if (couples || quad_couples)
    {
      EXPECT_TRUE(footprint.may_overlap(master)) << "shift " << 0.2 * step;
      ++coupled;
    }
    if (!footprint.may_overlap(master))
      ++dropped;
  }
  EXPECT_GT(coupled, 0);
  EXPECT_GT(dropped, 0);
}

// The same for an edge of a 2D cell (integrate_edge_segment): a line2 master slid along the
// slave's line.
TEST(MortarFaces, FootprintKeepsEveryMasterEdgeThatCouples)
{
  FaceGeometry slave;
  slave.kind = FaceKind::line2;
  slave.planar = {mesh::PlanarKind::plane_strain, 1.0};
  slave.x.resize(2, 3);
  slave.x << 0.0, 0.0, 0.0, 1.0, 0.1, 0.0;
  const SlaveFootprint footprint(slave);
  const FaceDualBasis dual = face_dual_basis(slave);
  int coupled = 0, dropped = 0;
  for (int step = -15; step <= 15; ++step)
  {
    FaceGeometry master = slave;
    master.x.row(0) = slave.x.row(1);
    master.x.row(1) = slave.x.row(0); // the other body's edge: reversed
    master.x.col(0).array() += 0.1 * step;
    if (integrate_face_segment(slave, dual, master).has_value())
    {
      EXPECT_TRUE(footprint.may_overlap(master)) << "shift " << 0.1 * step;
      ++coupled;
    }
    if (!footprint.may_overlap(master))
      ++dropped;
  }
  EXPECT_GT(coupled, 0);
  EXPECT_GT(dropped, 0);
}

std::string face_name(const ::testing::TestParamInfo<FaceKind>& info)
{
  constexpr std::array<const char*, 4> names = {"tri3", "tri6", "quad4", "quad8"};
  return names[static_cast<int>(info.param)];
}

INSTANTIATE_TEST_SUITE_P(EveryFaceType, MortarFaces,
                         ::testing::Values(FaceKind::tri3, FaceKind::tri6, FaceKind::quad4, FaceKind::quad8),
                         face_name);
} // namespace
} // namespace feticon::contact
