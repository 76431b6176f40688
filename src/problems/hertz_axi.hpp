#pragma once
/// @file Axisymmetric Hertz (issue 64): an elastic sphere of radius R pressed with the force P
/// onto an elastic half-space, modelled in the r-z plane by quad4 axisymmetric cells (x = r,
/// y along the axis). Analytic reference: Hertz's point contact (Johnson 1985, Contact
/// Mechanics, section 4.2), as for hertz3d: 1/E* = (1 - nu_1^2)/E_1 + (1 - nu_2^2)/E_2,
/// a = (3 P R / (4 E*))^(1/3), p0 = 3 P / (2 pi a^2), p(r) = p0 sqrt(1 - r^2 / a^2).
///
/// Geometry: the cross-section of the Hertz cylinder (hertz_mesh.hpp, its graded Gmsh mesh)
/// turned about the axis x = 0: body "sphere" (the set names keep the mesh's "cylinder_")
/// is the part of the sphere within r <= cylinder_width below its equator plane y = R, whose
/// disc carries a uniform downward traction of resultant P (P / (pi Xc^2)); body "block" is a
/// cylinder r <= block_width, depth block_depth, fixed at its bottom. The axis nodes are held
/// radially (u_r = 0; set "symmetry"); the sphere is held axially only by contact.
///
/// Defaults: R = 1 m, P = 4e7 N, steel on steel: a = 64.9 mm, p0 = 4.54 GPa, a / R = 0.065,
/// h = 2.5 mm at refinement 1 (hertz_axi.element_size; half the 2D benchmark's): 26 cells
/// across a, where small displacements give the peak and a within 0.4 % of Hertz.

#include "fem/problem.hpp"
#include "problems/built_in_problem.hpp"
#include "problems/hertz3d.hpp"
#include "problems/hertz_mesh.hpp"

#include <memory>
#include <optional>
#include <vector>

namespace feticon::problems
{
struct HertzAxiParameters
{
  HertzMeshParameters mesh = axisymmetric_mesh(); ///< cylinder_radius is the sphere's R
  double load = 4.0e7;                            ///< P on the sphere (N), the full circle
  fem::Material material{2.0e11, 0.3};            ///< the sphere's, and the block's if not given
  std::optional<fem::Material> block_material;    ///< the block's if it differs

  /// The same sphere and load as hertz3d's parameters (whose analytic solution is this one's).
  Hertz3dParameters as_3d() const;
  static HertzMeshParameters axisymmetric_mesh()
  {
    HertzMeshParameters p;
    p.axisymmetric = true;
    p.element_size = 0.0025;
    return p;
  }
};

/// The problem; throws feticon::Error naming a parameter out of range.
fem::Problem hertz_axi_problem(const HertzAxiParameters& parameters);

/// The `hertz_axi.*` keys (problems/built_in_problem.hpp).
std::vector<io::SettingSpec> hertz_axi_setting_specs();
std::unique_ptr<BuiltInProblem> make_hertz_axi_problem(const io::Settings& settings);
} // namespace feticon::problems
