/// Body loads (fem/body_loads.hpp): the consistent nodal forces of gravity and of a rotation
/// about an axis, on every cell type.

#include "common/error.hpp"
#include "fem/body_loads.hpp"
#include "mesh/box.hpp"
#include "mesh/cell_conversion.hpp"

#include <gtest/gtest.h>

using namespace feticon;

namespace
{
/// A sheared block (an affine map of the unit grid): every cell a parallelepiped of the
/// same volume, 0.8 x 0.6 x 0.5 m in all (the shear keeps the volume).
mesh::Mesh sheared_block(mesh::CellKind kind)
{
  const mesh::Mesh hex = mesh::generate_mapped_block(
      {4, 3, 2},
      [](int32_t i, int32_t j, int32_t k) { return Eigen::Vector3d(0.2 * i + 0.1 * k, 0.2 * j + 0.05 * i, 0.25 * k); },
      "block");
  return kind == mesh::CellKind::hex8 ? hex : mesh::convert_hex8_mesh(hex, kind);
}

constexpr double volume = 0.8 * 0.6 * 0.5;
const mesh::CellKind kinds[] = {mesh::CellKind::hex8, mesh::CellKind::hex20, mesh::CellKind::tet4,
                                mesh::CellKind::tet10, mesh::CellKind::wedge6};

Eigen::Vector3d total(const la::Vector& f)
{
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (la::Index n = 0; n < f.size() / 3; ++n)
    sum += f.segment<3>(3 * n);
  return sum;
}
} // namespace

// Reference: sum_a N_a = 1, so the nodal forces of gravity sum to rho g V exactly (the cells are
// parallelepipeds: constant Jacobian, integrated exactly by every rule).
TEST(BodyLoads, GravitySumsToTheWeightOnEveryCellType)
{
  for (const mesh::CellKind kind : kinds)
  {
    SCOPED_TRACE(mesh::cell_type(kind).name);
    const mesh::Mesh mesh = sheared_block(kind);
    fem::Material steel;
    steel.density = 7850;
    fem::BodyLoad gravity;
    gravity.gravity = Eigen::Vector3d(0.5, 0, -9.81);
    la::Vector f = la::Vector::Zero(3 * mesh.n_nodes());
    fem::add_body_load(mesh, {steel}, gravity, f);
    const Eigen::Vector3d expected = 7850 * volume * gravity.gravity;
    EXPECT_LT((total(f) - expected).norm(), 1e-12 * expected.norm());
  }
}

// Reference: the resultant of rho omega^2 r_perp over a body is rho omega^2 V times the
// centroid's distance from the axis (the integrand is linear in x: exact on parallelepipeds).
// The block's centroid is the map at the grid's centre (i, j, k) = (2, 1.5, 1): (0.5, 0.4, 0.25).
TEST(BodyLoads, CentrifugalResultantIsMassTimesCentroidAcceleration)
{
  for (const mesh::CellKind kind : kinds)
  {
    SCOPED_TRACE(mesh::cell_type(kind).name);
    const mesh::Mesh mesh = sheared_block(kind);
    fem::Material steel;
    steel.density = 7850;
    fem::BodyLoad spin;
    spin.kind = fem::BodyLoad::Kind::centrifugal;
    spin.omega2 = 100.0 * 100.0;
    spin.point = Eigen::Vector3d(0.1, -0.2, 3.0);
    spin.axis = Eigen::Vector3d(0, 0, 2); // normalized on use
    la::Vector f = la::Vector::Zero(3 * mesh.n_nodes());
    fem::add_body_load(mesh, {steel}, spin, f);
    const Eigen::Vector3d centroid(0.5, 0.4, 0.25);
    const Eigen::Vector3d r = centroid - spin.point;
    const Eigen::Vector3d expected = 7850 * volume * spin.omega2 * Eigen::Vector3d(r.x(), r.y(), 0);
    EXPECT_LT((total(f) - expected).norm(), 1e-12 * expected.norm());
  }
}

TEST(BodyLoads, LoadOnABodyWithoutDensityIsNamed)
{
  const mesh::Mesh mesh = sheared_block(mesh::CellKind::hex8);
  fem::BodyLoad gravity;
  gravity.gravity = Eigen::Vector3d(0, 0, -9.81);
  gravity.where = "deck.inp:12: *DLOAD GRAV";
  la::Vector f = la::Vector::Zero(3 * mesh.n_nodes());
  try
  {
    fem::add_body_load(mesh, {fem::Material{}}, gravity, f);
    FAIL() << "no error";
  }
  catch (const Error& e)
  {
    EXPECT_NE(std::string(e.what()).find("deck.inp:12: *DLOAD GRAV: body block has no density"), std::string::npos)
        << e.what();
  }
  fem::BodyLoad spin;
  spin.kind = fem::BodyLoad::Kind::centrifugal;
  spin.axis = Eigen::Vector3d::Zero();
  fem::Material steel;
  steel.density = 7850;
  EXPECT_THROW(fem::add_body_load(mesh, {steel}, spin, f), Error);
}
