#pragma once
/// @file The Hertz benchmark of Vondrák, Dostál, Dobiáš and Pták (DD XVI, 2007, section 6):
/// a cylinder of radius R1 = 1 m on a half-space, both steel (E = 2e11 Pa, nu = 0.3), line
/// load Q = 4e8 N/m, plane strain, modelled with symmetry about x = 0. Analytic reference: Hertz / McEwen (Johnson 1985,
/// ch. 4; ALGORITHMS.md section 9).
///
/// Boundary conditions of the half model: u_x = 0 on the symmetry plane x = 0 (both
/// bodies), the block's bottom fixed, u_z = 0 everywhere (eliminated), and the half load
/// Q/2 per unit length as a uniform downward traction on the cylinder's top face y = R1.
/// The cylinder is held vertically only by contact.

#include "fem/problem.hpp"
#include "problems/built_in_problem.hpp"
#include "problems/hertz_mesh.hpp"
#include "problems/pressure_profile.hpp"

#include <optional>
#include <vector>

namespace feticon::problems
{
struct HertzParameters
{
  HertzMeshParameters mesh;
  double line_load = 4.0e8; ///< Q (N/m) on the whole cylinder; the half model carries Q/2
  /// Tangential line load (N/m, along +x) applied after the normal one, in a second load
  /// stage: Cattaneo-Mindlin with friction. Non-zero: the full model (mesh.full).
  double tangential_load = 0;
  /// Instead of tangential_load: the load face moved along +x by this much (m) in the second
  /// stage (held at u_x = 0 in the first), with the couple of the full slide's force mu P
  /// (or of tangential_couple):
  /// Cattaneo-Mindlin's Q >= mu P, where force control has no unique answer. Needs
  /// friction_coefficient > 0 (Coulomb); non-zero: the full model (mesh.full).
  double tangential_displacement = 0;
  /// With tangential_displacement: the tangential line load (N/m) whose moment about the
  /// contact the load face's couple cancels, the force the moved face is expected to carry.
  /// 0: mu P, the full slide. Non-zero: displacement-controlled partial slip, compared with
  /// Cattaneo-Mindlin at the force the face carries (the tangential reaction): with large
  /// displacements force control leaves the cylinder free to roll on its contact (neutral:
  /// docs/friction.md), the moved face holds it.
  double tangential_couple = 0;
  /// With tangential_load: a third load stage lowers the tangential load to this (N/m), in
  /// (0, tangential_load): Mindlin-Deresiewicz unloading, whose answer is the path's.
  std::optional<double> unloaded_tangential_load;
  double friction_coefficient = 0;             ///< Coulomb's mu (contact.friction), for Cattaneo-Mindlin; 0: none
  fem::Material material{2.0e11, 0.3};         ///< the cylinder's, and the block's if not given
  std::optional<fem::Material> block_material; ///< the block's if it differs
  fem::Material block() const { return block_material.value_or(material); }
  /// The Q (N/m) applied at the end, or expected of a tangential displacement: tangential_load
  /// (unloaded_tangential_load where given), or tangential_couple (mu P for the full slide if
  /// not given); 0 without either.
  double compared_tangential_load() const
  {
    if (tangential_displacement > 0)
      return tangential_couple > 0 ? tangential_couple : friction_coefficient * line_load;
    return unloaded_tangential_load.value_or(tangential_load);
  }
};

/// The problem: bodies "cylinder" (slave surface "cylinder_contact") and "block" (master
/// surface "block_contact").
fem::Problem hertz_problem(const HertzParameters& parameters);

/// Analytic plane-strain Hertz line contact (frictionless, so dissimilar materials enter only
/// through E*).
struct HertzAnalytic
{
  double effective_modulus; ///< E* (Pa), fem::contact_modulus of the two bodies
  double half_width;        ///< a = sqrt(4 Q R / (pi E*)) (m)
  double peak_pressure;     ///< p0 = 2 Q / (pi a) (Pa)
  /// p(x) = p0 sqrt(1 - x^2/a^2) for |x| <= a, else 0 (Pa).
  double pressure(double x) const;
};
HertzAnalytic hertz_analytic(const HertzParameters& parameters);

/// Downward displacement of the cylinder's axis under u: the mean u_y of the load face
/// y = R1, which passes through the axis (m).
double hertz_axis_approach(const fem::Problem& problem, const la::Vector& u);

/// The load face's mean displacement along x (m): what a tangential load moves it by, the d
/// that tangential_displacement needs to give the same force under displacement control.
double hertz_load_face_shift(const fem::Problem& problem, const la::Vector& u);

/// The force along x (N) that the load face's support exerts on the cylinder under a
/// tangential displacement: the internal forces of the face's nodes, whose loads (the normal
/// traction and the couple) have no x part. It balances the contact's tangential reaction.
double hertz_load_face_support_force(const fem::Problem& problem, const la::Vector& u, fem::Kinematics kinematics);

/// The figures against McEwen's profile, all in the frame of the samples: the deformed
/// coordinate x + u_x for large displacements (the pressure is per deformed area and the slave
/// nodes move by up to 0.45 mm at the contact edge) or the reference x.
struct HertzComparison
{
  double a_analytic = 0, p0_analytic = 0;
  double a_computed = 0;      ///< from the fit of p^2 (fitted_half_width)
  double p_peak_computed = 0; ///< largest nodal pressure from the multipliers
  /// RMS of p - p_McEwen over 400 equidistant points of [0, a_analytic], p interpolated
  /// linearly between samples, over p0 (bench/calculix_compare.py computes the same).
  double rms_error_over_p0 = 0;
  double element_size = 0; ///< sample spacing at x = a_computed (m)
  double applied_load = 0; ///< Q/2 * thickness (N) carried by the half model, Q * thickness by the full
};

/// The figures; `samples` are the slave node lines at their distance r = x from the
/// symmetry plane.
HertzComparison compare_with_hertz(const HertzParameters& parameters, std::vector<ProfilePoint> samples);

/// The `hertz.*` keys (problems/built_in_problem.hpp).
std::vector<io::SettingSpec> hertz_setting_specs();
/// The parameters of the `hertz.*` and `material.*` settings.
HertzParameters hertz_parameters(const io::Settings& settings);
std::unique_ptr<BuiltInProblem> make_hertz_problem(const io::Settings& settings);
} // namespace feticon::problems
