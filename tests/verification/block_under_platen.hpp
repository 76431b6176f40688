#pragma once
/// A block pressed by a platen under a prescribed displacement, the set-up of the material tests
/// through contact (test_plastic_compression.cpp, test_rubber_compression.cpp): the block (body
/// "block") held at z = 0, the platen (body "platen", sets prefixed "platen_") on its top face
/// through a frictionless mortar pair, both on the symmetry planes x = 0 and y = 0, the platen's
/// top moved down by each step's entry of `press` (depth in m, increments).

#include "fem/problem.hpp"
#include "mesh/box.hpp"

#include <string>
#include <utility>
#include <vector>

namespace block_under_platen
{
/// @param materials  the block's, then the platen's
/// @param platen_is_slave  the platen's bottom is the pair's slave surface (else the block's top)
inline feticon::fem::Problem pressed_block(std::string name, feticon::mesh::BoxParameters block,
                                           feticon::mesh::BoxParameters platen,
                                           std::vector<feticon::fem::Material> materials,
                                           const std::vector<std::pair<double, int>>& press, bool platen_is_slave)
{
  using namespace feticon;
  fem::Problem p;
  p.name = std::move(name);
  block.body_name = "block";
  platen.body_name = "platen";
  platen.origin = Eigen::Vector3d(0, 0, block.origin(2) + block.lengths(2));
  p.mesh = mesh::generate_box(block);
  mesh::append_mesh(p.mesh, mesh::generate_box(platen), "platen_");
  p.materials = std::move(materials);
  p.steps.clear();
  for (const auto& [depth, increments] : press)
  {
    fem::Step step;
    for (const std::string prefix : {"", "platen_"})
    {
      step.dirichlet.push_back({prefix + "xmin", {0.0, std::nullopt, std::nullopt}});
      step.dirichlet.push_back({prefix + "ymin", {std::nullopt, 0.0, std::nullopt}});
    }
    step.dirichlet.push_back({"zmin", {std::nullopt, std::nullopt, 0.0}});
    step.dirichlet.push_back({"platen_zmax", {std::nullopt, std::nullopt, -depth}});
    step.increments = increments;
    p.steps.push_back(step);
  }
  if (platen_is_slave)
    p.contacts.push_back({"platen_zmin", "zmax"});
  else
    p.contacts.push_back({"zmax", "platen_zmin"});
  p.validate();
  return p;
}
} // namespace block_under_platen
