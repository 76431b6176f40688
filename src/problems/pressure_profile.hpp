#pragma once
/// @file Contact pressure along one coordinate, the distance r from the symmetry plane x = 0
/// (2D Hertz) or from the axis (3D Hertz), and the fit of Hertz's elliptic profile to it: the
/// part the 2D and 3D comparisons with the analytic solutions share.

#include <vector>

namespace feticon::problems
{
/// A sample carries contact force when its pressure exceeds this fraction of the largest:
/// the one activity threshold of the Hertz figures (fit of a, loaded area).
constexpr double loaded_fraction = 1e-3;

/// One slave node's (in plane strain: node line's) pressure at its coordinate r, in the frame
/// of the comparison (reference or deformed).
struct ProfilePoint
{
  double r = 0;        ///< (m)
  double pressure = 0; ///< (Pa)
};

/// Largest pressure of the samples (0 if there are none).
double peak_pressure(const std::vector<ProfilePoint>& samples);

/// Half-width (2D) or contact radius (3D) a from the least-squares fit
/// p^2 = p0^2 (1 - r^2/a^2) over the loaded samples, so that one lightly loaded node does not
/// move it by an element; 0 if fewer than two samples are loaded or the fit is no ellipse.
double fitted_half_width(const std::vector<ProfilePoint>& samples);
} // namespace feticon::problems
