#pragma once
/// Two-block contact problems for the verification tests.

#include "fem/problem.hpp"
#include "mesh/box.hpp"

namespace feticon::test
{
/// Lower block [0,1]^2 x [0,1] and upper block [0,1]^2 x [1 + gap, 2 + gap], upper zmin
/// (slave) against lower zmax (master). Roller supports: u_x = 0 on both xmin faces,
/// u_y = 0 on both ymin faces, u_z = 0 on the lower zmin; a uniform pressure p on the upper
/// zmax. The exact solution is uniaxial stress with contact pressure p everywhere: the FE
/// space contains it (linear field), so a consistent contact discretization must give it.
inline fem::Problem pressed_blocks(int n_lower, int n_upper, double gap, double pressure)
{
  mesh::BoxParameters lower;
  lower.nx = lower.ny = lower.nz = n_lower;
  lower.body_name = "lower";
  mesh::BoxParameters upper;
  upper.origin = Eigen::Vector3d(0, 0, 1 + gap);
  upper.nx = upper.ny = upper.nz = n_upper;
  upper.body_name = "upper";
  fem::Problem p;
  p.name = "pressed blocks";
  p.mesh = mesh::generate_box(lower);
  mesh::append_mesh(p.mesh, mesh::generate_box(upper), "upper_");
  p.materials.assign(2, fem::Material{2e11, 0.3});
  p.steps.front().dirichlet = {{"xmin", {0.0, std::nullopt, std::nullopt}},
                               {"upper_xmin", {0.0, std::nullopt, std::nullopt}},
                               {"ymin", {std::nullopt, 0.0, std::nullopt}},
                               {"upper_ymin", {std::nullopt, 0.0, std::nullopt}},
                               {"zmin", {std::nullopt, std::nullopt, 0.0}}};
  p.steps.front().tractions = {{"upper_zmax", Eigen::Vector3d(0, 0, -pressure)}};
  p.contacts = {{"upper_zmin", "zmax"}};
  p.validate();
  return p;
}
} // namespace feticon::test
