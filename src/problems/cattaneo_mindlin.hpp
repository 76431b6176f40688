#pragma once
/// @file Cattaneo-Mindlin partial slip of the Hertz cylinder (plane strain; Cattaneo 1938,
/// Mindlin 1949; Johnson, Contact Mechanics (1985), section 7.2): pressed by P (N/m), then
/// pulled along x by Q (N/m) with Coulomb friction mu and no rotation, the cylinder sticks on
/// |x| < c = a sqrt(1 - Q / (mu P)) and slides on c < |x| < a, with the shear traction
///   q(x) = mu p0 sqrt(1 - x^2/a^2) - [|x| < c] mu p0 (c/a) sqrt(1 - x^2/c^2)
/// (for similar materials the pressure stays Hertz's); Q >= mu P slides everywhere, q = mu p.
/// The friction traction on the cylinder opposes Q: -q(x) along x. The comparison with a run
/// fills summary.json's `friction` block.

#include "problems/built_in_problem.hpp"

#include <vector>

namespace feticon::problems
{
struct CattaneoMindlin
{
  double coefficient = 0;      ///< mu
  double peak_pressure = 0;    ///< p0 (Pa)
  double half_width = 0;       ///< a (m)
  double stick_half_width = 0; ///< c (m)
  /// The friction traction on the cylinder along x at x (Pa): -q(x).
  double shear(double x) const;
};

/// @param line_load, tangential_load  P and Q (N/m); Q >= 0
CattaneoMindlin cattaneo_mindlin(double coefficient, double peak_pressure, double half_width, double line_load,
                                 double tangential_load);

/// The figures of the samples (`x` in the frame of the comparison, ascending or not) against
/// the theory: `coefficient`, `tangential_force` (N, the friction forces on the cylinder along
/// x), `applied_tangential_force` (N) and their relative mismatch, the stick-zone half-widths
/// (computed: half the span between the midpoints from the outermost sticking loaded samples
/// to their sliding neighbours), `shear_rms_error_over_mu_p0` (RMS of shear - theory over the
/// samples within [-a, a]), the same for the symmetric part of the shear (q(x) + q(-x))/2 and
/// the RMS of its antisymmetric part, sliding and sticking loaded samples. Why both parts: the
/// theory's shear is symmetric, and it neglects the antisymmetric shear that friction leaves
/// after the normal load on a cylinder (not a half-space: about a/R of mu p0, measured in
/// docs/friction.md).
nlohmann::ordered_json cattaneo_mindlin_figures(const CattaneoMindlin& theory,
                                                const std::vector<SurfaceSample>& samples, const std::vector<double>& x,
                                                double applied_tangential_force);
} // namespace feticon::problems
