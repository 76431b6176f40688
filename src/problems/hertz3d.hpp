#pragma once
/// @file 3D Hertz (issue 20): an elastic sphere of radius R pressed with the force F onto an
/// elastic half-space, quarter model (symmetry planes x = 0 and y = 0); with a tangential load
/// along x (Cattaneo-Mindlin, after the normal load in a second load stage) the half model
/// y >= 0 (the octant balls mirrored across x = 0).
/// Analytic reference: Hertz's point contact (Johnson 1985, Contact Mechanics, section 4.2):
/// 1/E* = (1 - nu_1^2)/E_1 + (1 - nu_2^2)/E_2 (frictionless: dissimilar materials enter only
/// through E*), a = (3 F R / (4 E*))^(1/3), p0 = 3 F / (2 pi a^2),
/// p(r) = p0 sqrt(1 - r^2 / a^2), approach delta = a^2 / R.
///
/// Geometry (m). The first contact point is the origin, the sphere's centre (0, 0, R).
///  - body 0 "sphere": the part of the sphere within cap_radius of the contact point, meshed
///    as an octant ball (mesh/octant_ball.hpp) in (x, y, d) mapped by
///    z = d + (R - sqrt(R^2 - x^2 - y^2)) (1 - d / cap_radius), which lays the ball's flat face
///    exactly on the sphere. Its far face "sphere_load" carries a
///    uniform downward traction whose resultant is F / 4 (F / 2 in the half model); the sphere
///    is held vertically only by contact. The tangential load Q (half model: Q / 2) is a uniform
///    traction along x on the same face, with a normal traction k x that cancels its moment
///    about the contact point (as hertz.cpp's moment_free_couple in 2D).
///  - body 1 "block": the half-space truncated to the octant ball of radius block_radius
///    below z = 0 (z = -d), fixed on its curved face "block_support".
/// With gmsh_mesh the same bodies are OpenCASCADE solids (the sphere cut to the ball of
/// cap_radius about the contact point) meshed by Gmsh with graded tetrahedra, and the sets the same.
/// Both meshes are graded from h = element_size / refinement (sphere) and master_ratio h
/// (block) in a uniform core covering 1.25 a out to cells `radial_aspect` times longer radially
/// than tangentially and proportional in size to the distance from the contact; the contact
/// meshes do not match.
///
/// Sets (faces outward from their body; every face set is also a node set):
///   "sphere_contact" (slave), "block_contact" (master, z = 0), "sphere_load",
///   "block_support", "symmetry_x" (x = 0, both bodies), "symmetry_y" (y = 0, both bodies).

#include "fem/problem.hpp"
#include "problems/built_in_problem.hpp"
#include "problems/pressure_profile.hpp"

#include <optional>
#include <vector>

namespace feticon::problems
{
struct Hertz3dParameters
{
  double radius = 0.05;       ///< R, sphere radius (m)
  double load = 2.0e4;        ///< F on the whole sphere (N); the quarter model carries F / 4
  double tangential_load = 0; ///< Q along +x on the whole sphere (N), after F; > 0: half model
  /// Instead of tangential_load: the load face moved along +x by this much (m) after F (held
  /// at u_x = 0 before), with the couple of the full slide's force mu F: Q >= mu P, which
  /// force control cannot drive. Needs friction_coefficient > 0; > 0: half model.
  double tangential_displacement = 0;
  double friction_coefficient = 0;             ///< Coulomb's mu (contact.friction), for Cattaneo-Mindlin; 0: none
  fem::Material material{2.0e11, 0.3};         ///< the sphere's, and the block's if not given
  std::optional<fem::Material> block_material; ///< the block's if it differs
  double element_size = 2.5e-4;                ///< slave cell size in the contact core at refinement 1 (m)
  double refinement = 1;                       ///< divides element_size
  double master_ratio = 1.3;                   ///< block / sphere cell size in the contact core
  double block_radius = 0.04;                  ///< radius of the modelled half-space (m)
  double cap_radius = 0.025;                   ///< radius of the modelled part of the sphere (m), <= R / 2
  double radial_aspect = 1.5;                  ///< radial / tangential cell size away from the core
  /// Cell type: hex8 as meshed, or those cells converted (mesh/cell_conversion.hpp), the
  /// quadratic cells' edge nodes on the sphere where the edge lies on it.
  mesh::CellKind cell = mesh::CellKind::hex8;
  /// Instead of the octant balls: the sphere cut to the ball of cap_radius and the block cut
  /// to the ball of block_radius as OpenCASCADE solids, meshed by Gmsh with tetrahedra (cell
  /// tet10 or tet4; quarter model only) of size element_size / refinement times the order
  /// within 1.25 a of the contact point, growing by gmsh_growth per metre beyond. 1.5: the
  /// tet10 meshes' pressure error per DOF fell from 0.25 to 1.5 and no further at 2
  /// (docs/elements.md, eighteenth session).
  bool gmsh_mesh = false;
  double gmsh_growth = 1.5;
  fem::Material block() const { return block_material.value_or(material); }
  bool half_model() const { return tangential_load > 0 || tangential_displacement > 0; }
  /// The Q (N, whole sphere) that Mindlin is compared with: tangential_load, or mu F for the
  /// full slide a tangential displacement drives.
  double compared_tangential_load() const
  {
    return tangential_displacement > 0 ? friction_coefficient * load : tangential_load;
  }
  /// The fraction of the sphere modelled: 1/4 or 1/2.
  double modelled() const { return half_model() ? 0.5 : 0.25; }
};

struct Hertz3dAnalytic
{
  double effective_modulus; ///< E* (Pa)
  double contact_radius;    ///< a (m)
  double peak_pressure;     ///< p0 (Pa)
  double approach;          ///< delta = a^2 / R (m)
  /// p(r) = p0 sqrt(1 - r^2 / a^2) for r <= a, else 0 (Pa).
  double pressure(double r) const;
};
Hertz3dAnalytic hertz3d_analytic(const Hertz3dParameters& parameters);

/// The problem; throws feticon::Error naming a parameter out of range.
fem::Problem hertz3d_problem(const Hertz3dParameters& parameters);

/// Nodes of the mesh hertz3d_problem builds, counted without building it (memory guard).
/// @throws feticon::Error as hertz3d_problem for parameters out of range
int64_t hertz3d_node_count(const Hertz3dParameters& parameters);

/// Approach of the sphere under the displacement u: the area-weighted mean of -u_z over its
/// loaded far face, relative to the block's fixed far face (m).
double hertz3d_approach(const fem::Problem& problem, const la::Vector& u);

struct Hertz3dComparison
{
  double a_analytic = 0, p0_analytic = 0, approach_analytic = 0;
  /// Contact radius from the fit of p^2 (fitted_half_width).
  double a_computed = 0;
  double p_peak_computed = 0; ///< largest nodal pressure
  /// RMS over the slave nodes with r <= a_analytic of p - p_Hertz(r), over p0.
  double rms_error_over_p0 = 0;
  int nodes_in_rms = 0;
};
/// The figures against Hertz's p(r), the samples at their distance r from the axis.
Hertz3dComparison compare_with_hertz3d(const Hertz3dParameters& parameters, const std::vector<ProfilePoint>& samples);

/// The `hertz3d.*` keys (problems/built_in_problem.hpp).
std::vector<io::SettingSpec> hertz3d_setting_specs();
/// The parameters of the `hertz3d.*` and `material.*` settings.
Hertz3dParameters hertz3d_parameters(const io::Settings& settings);
std::unique_ptr<BuiltInProblem> make_hertz3d_problem(const io::Settings& settings);
} // namespace feticon::problems
