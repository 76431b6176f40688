#pragma once
/// @file Cattaneo-Mindlin partial slip of the Hertz cylinder (plane strain; Cattaneo 1938,
/// Mindlin 1949; Johnson, Contact Mechanics (1985), section 7.2): pressed by P (N/m), then
/// pulled along x by Q (N/m) with Coulomb friction mu and no rotation, the cylinder sticks on
/// |x| < c = a sqrt(1 - Q / (mu P)) and slides on c < |x| < a, with the shear traction
///   q(x) = mu p0 sqrt(1 - x^2/a^2) - [|x| < c] mu p0 (c/a) sqrt(1 - x^2/c^2)
/// (for similar materials the pressure stays Hertz's); Q >= mu P slides everywhere, q = mu p.
/// The friction traction on the cylinder opposes Q: -q(x) along x. The comparison with a run
/// fills summary.json's `friction` block.
///
/// Unloaded from Q* to Q (0 < Q < Q*: Mindlin and Deresiewicz 1953; Johnson section 7.2 and
/// fig. 7.9), the cylinder slips back on c' < |x| < a, c' = a sqrt(1 - (Q* - Q) / (2 mu P)), and
///   q(x) = q*(x) - 2 q'(x),
/// q* the loaded traction above and q' the same form with c' for c; inside c' nothing moved.
///
/// The sphere (Mindlin 1949; Johnson section 7.2, eqs. 7.49-7.51): pressed by P (N), pulled
/// by Q (N), it sticks on r < c = a (1 - Q / (mu P))^(1/3), with the same q(r) as above in the
/// distance r from the axis and the traction along x. (In the slip annulus the theory takes the
/// slip parallel to x, which Johnson notes is approximate for nu > 0; in the stick zone its
/// displacement is exactly uniform.)

#include "problems/built_in_problem.hpp"

#include <optional>
#include <string>
#include <vector>

namespace feticon::problems
{
struct CattaneoMindlin
{
  double coefficient = 0;      ///< mu
  double peak_pressure = 0;    ///< p0 (Pa)
  double half_width = 0;       ///< a (m)
  double stick_half_width = 0; ///< c (m); unloaded: c'
  /// Unloaded (mindlin_deresiewicz): the stick half-width c* at the peak load Q*.
  std::optional<double> peak_stick_half_width;
  /// The friction traction on the cylinder along x at x (Pa): -q(x).
  double shear(double x) const;
};

enum class HertzContact
{
  cylinder, ///< plane strain: c = a sqrt(1 - Q / (mu P))
  sphere,   ///< c = a (1 - Q / (mu P))^(1/3)
};

/// @param line_load, tangential_load  P and Q (N/m for the cylinder, N for the sphere); Q >= 0
/// @param half_width  a: the half-width (cylinder) or contact radius (sphere)
CattaneoMindlin cattaneo_mindlin(double coefficient, double peak_pressure, double half_width, double line_load,
                                 double tangential_load, HertzContact contact = HertzContact::cylinder);

/// The cylinder pressed by P, pulled by peak_load Q* < mu P and unloaded to Q in (0, Q*).
CattaneoMindlin mindlin_deresiewicz(double coefficient, double peak_pressure, double half_width, double line_load,
                                    double peak_load, double tangential_load);

/// The friction and normal contact forces on the slave body along x, summed over the samples
/// (N): the tangential reaction, which balances Q (with large displacements the contact
/// surface turns and the normal forces carry part of it).
double tangential_reaction(const std::vector<SurfaceSample>& samples);

/// The figures of the samples (`x` in the frame of the comparison, ascending or not) against
/// the theory: `coefficient`, `tangential_force` (N, the friction forces on the cylinder along
/// x), `applied_tangential_force` (N) and their relative mismatch, `tangential_reaction` (N,
/// the friction and the normal forces on the cylinder along x: with large displacements the
/// contact surface turns and the normal forces carry part of Q) and its relative mismatch
/// `tangential_reaction_error`, the stick-zone half-widths
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

/// The sphere's figures (half model y >= 0, mirror symmetric across x = 0): the same keys as
/// cattaneo_mindlin_figures, with the samples at their distance from the axis and
///  - the stick radius from the area of the loaded sticking samples, c = sqrt(2 A_stick / pi)
///    (a half disc; the edge of the zone is a circle, so its cells' errors average out where
///    the outermost sticking node's radius would be one cell off);
///  - the RMS over the samples with r <= a of shear_x - theory and of shear_y (the theory's 0),
///    and the part of shear_x symmetric across x = 0 (the sample at (-x, y) is the mirror node).
/// `deformed`: the samples' deformed coordinates for r.
nlohmann::ordered_json cattaneo_mindlin_sphere_figures(const CattaneoMindlin& theory,
                                                       const std::vector<SurfaceSample>& samples, bool deformed,
                                                       double applied_tangential_force);

/// The line of the end-of-run table for a `friction` block `f`; `zone`: "half-width" or "radius".
std::string cattaneo_mindlin_line(const nlohmann::ordered_json& f, const CattaneoMindlin& theory, double applied,
                                  const std::string& zone);
} // namespace feticon::problems
