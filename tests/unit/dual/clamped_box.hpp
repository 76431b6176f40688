#pragma once
/// The FETI test system of the dual-layer unit tests: a 3 x 1 x 1 box of 6 x 2 x 2 cells,
/// clamped at x = 0, in three subdomains (x = 1 and x = 2 are interfaces).

#include "decomposition/constraint_rows.hpp"
#include "decomposition/subdomain_operators.hpp"
#include "mesh/box.hpp"

#include <memory>

namespace feticon::test
{
struct ClampedBox
{
  mesh::Mesh mesh;
  std::unique_ptr<decomposition::Decomposition> decomp;
  std::unique_ptr<decomposition::SubdomainSystem> system;
  decomposition::EqualityRows equality; ///< gluing rows and the clamp's Dirichlet rows
};

inline std::unique_ptr<ClampedBox> make_clamped_box()
{
  auto s = std::make_unique<ClampedBox>();
  mesh::BoxParameters p;
  p.lengths = Eigen::Vector3d(3, 1, 1);
  p.nx = 6;
  p.ny = 2;
  p.nz = 2;
  s->mesh = mesh::generate_box(p);
  s->decomp =
      std::make_unique<decomposition::Decomposition>(s->mesh, decomposition::partition_structured(s->mesh, {3, 1, 1}));
  s->system = std::make_unique<decomposition::SubdomainSystem>(*s->decomp, std::vector<fem::Material>{fem::Material{}},
                                                               fem::Kinematics::linear,
                                                               decomposition::GeneralizedInverseMethod::fixing_dofs);
  s->system->update(la::Vector::Zero(s->decomp->n_primal()));
  s->equality =
      decomposition::build_equality_rows(*s->decomp, fem::collect_dirichlet(s->mesh, {{"xmin", {0.0, 0.0, 0.0}}}));
  return s;
}
} // namespace feticon::test
