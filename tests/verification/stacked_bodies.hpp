#pragma once
/// Stacks of bodies with non-matching meshes for the verification tests of contact pairs and
/// ties: under a uniform traction on rollers their exact solution is a uniaxial stress, which
/// every cell type represents (test_assemblies.cpp, test_planar_mortar.cpp, test_ties.cpp).

#include "contact/tie_rows.hpp"
#include "fem/problem.hpp"
#include "mesh/box.hpp"
#include "mesh/rectangle.hpp"

#include <algorithm>
#include <functional>
#include <string>
#include <vector>

namespace feticon::test
{
inline constexpr double stack_young = 2e11, stack_poisson = 0.3;

/// Unit cubes stacked along z, body k on [k, k + 1] with cells[k] cells along each axis (so
/// neighbours' contact faces do not match), held by symmetry planes x = 0 and y = 0 and the
/// bottom z = 0, the top loaded by the dead traction (0, 0, traction_z) on its reference face;
/// contact pair k: the bottom of body k + 1 (slave) on the top of body k (master).
inline fem::Problem stacked_cubes(const std::vector<int>& cells, double traction_z)
{
  fem::Problem p;
  p.name = "stacked cubes";
  for (size_t k = 0; k < cells.size(); ++k)
  {
    mesh::BoxParameters box;
    box.origin = Eigen::Vector3d(0, 0, static_cast<double>(k));
    box.nx = box.ny = box.nz = cells[k];
    box.body_name = "body" + std::to_string(k);
    const std::string prefix = k == 0 ? "" : box.body_name + "_";
    if (k == 0)
      p.mesh = mesh::generate_box(box);
    else
      mesh::append_mesh(p.mesh, mesh::generate_box(box), prefix);
    p.steps.front().dirichlet.push_back({prefix + "xmin", {0.0, std::nullopt, std::nullopt}});
    p.steps.front().dirichlet.push_back({prefix + "ymin", {std::nullopt, 0.0, std::nullopt}});
    if (k > 0)
      p.contacts.push_back({prefix + "zmin", (k == 1 ? std::string() : "body" + std::to_string(k - 1) + "_") + "zmax"});
  }
  p.steps.front().dirichlet.push_back({"zmin", {std::nullopt, std::nullopt, 0.0}});
  const std::string top = cells.size() == 1 ? "zmax" : "body" + std::to_string(cells.size() - 1) + "_zmax";
  p.steps.front().tractions = {{top, Eigen::Vector3d(0, 0, traction_z)}};
  p.materials.assign(cells.size(), fem::Material{stack_young, stack_poisson});
  p.validate();
  return p;
}

/// Block [0, 0.5] x [-0.4, 0] ("lower") of n x n cells under [0, 0.5] x [0, 0.4] ("upper") of
/// (n + 2) x (n + 1), thickness 0.1 in plane strain: non-matching at y = 0; on rollers (u_y = 0
/// at the bottom, u_x = 0 at x = 0 but in axisymmetry, where the axis holds itself); the top
/// under the dead pressure `pressure` (negative: a pull); one mortar pair, the upper block's
/// bottom on the lower block's top.
inline fem::Problem stacked_blocks(mesh::CellKind kind, mesh::PlanarKind planar, int n, double pressure)
{
  fem::Problem p;
  p.name = "planar patch";
  p.eliminated = {false, false, true};
  const mesh::Planar formulation{planar, 0.1};
  p.mesh = mesh::generate_rectangle({.origin = {0, -0.4},
                                     .lengths = {0.5, 0.4},
                                     .nx = n,
                                     .ny = n,
                                     .kind = kind,
                                     .planar = formulation,
                                     .body_name = "lower"});
  mesh::append_mesh(p.mesh,
                    mesh::generate_rectangle({.origin = {0, 0},
                                              .lengths = {0.5, 0.4},
                                              .nx = n + 2,
                                              .ny = n + 1,
                                              .kind = kind,
                                              .planar = formulation,
                                              .body_name = "upper"}),
                    "upper_");
  p.materials = {fem::Material{stack_young, stack_poisson}, fem::Material{stack_young, stack_poisson}};
  fem::Step step;
  step.dirichlet.push_back({"ymin", {std::nullopt, 0.0, std::nullopt}});
  if (planar != mesh::PlanarKind::axisymmetric)
  {
    step.dirichlet.push_back({"xmin", {0.0, std::nullopt, std::nullopt}});
    step.dirichlet.push_back({"upper_xmin", {0.0, std::nullopt, std::nullopt}});
  }
  step.pressures.push_back({"upper_ymax", pressure});
  p.steps = {step};
  p.contacts.push_back({"upper_ymin", "ymax"});
  p.contacts[0].interaction.formulation = fem::ContactFormulation::mortar;
  p.validate();
  return p;
}

/// The contact pairs `pairs` (indices) made ties "T1", "T2", ... (by index + 1), their rows made.
inline void tie_pairs(fem::Problem& p, std::vector<size_t> pairs)
{
  std::ranges::sort(pairs, std::greater<>());
  for (const size_t k : pairs)
  {
    p.ties.insert(p.ties.begin(), {"T" + std::to_string(k + 1), p.contacts[k].slave, p.contacts[k].master});
    p.contacts.erase(p.contacts.begin() + static_cast<std::ptrdiff_t>(k));
  }
  p.validate();
  contact::tie_surfaces(p);
}
} // namespace feticon::test
