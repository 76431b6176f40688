#pragma once
/// @file What the 2D (McEwen) and 3D (Hertz's sphere) comparisons share: the pressure profile
/// at the distance from the symmetry plane or the axis, and summary.json's `hertz` block with
/// its line of the end-of-run table.

#include "problems/built_in_problem.hpp"
#include "problems/pressure_profile.hpp"

#include <cmath>
#include <cstdio>
#include <vector>

namespace feticon::problems
{
/// The samples at their distance r from the symmetry plane x = 0 (`radial` false) or from the
/// axis x = y = 0, in the deformed or the reference frame.
inline std::vector<ProfilePoint> pressure_profile(const std::vector<SurfaceSample>& samples, bool radial, bool deformed)
{
  std::vector<ProfilePoint> out;
  out.reserve(samples.size());
  for (const SurfaceSample& s : samples)
  {
    const double x = deformed ? s.deformed_x : s.x, y = deformed ? s.deformed_y : s.y;
    out.push_back({radial ? std::hypot(x, y) : x, s.pressure});
  }
  return out;
}

/// The `hertz` block of the figures `h` (in the deformed frame with large displacements, whose
/// reference frame's figures are `reference`), carrying `applied_load` (N).
template <class Comparison>
TheoryComparison hertz_theory_comparison(const Comparison& h, const Comparison& reference, bool large,
                                         double applied_load)
{
  TheoryComparison out;
  out.name = "hertz";
  out.applied_load = applied_load;
  out.figures = {{"frame", large ? "deformed" : "reference"},
                 {"a_analytic", h.a_analytic},
                 {"p0_analytic", h.p0_analytic},
                 {"a_computed", h.a_computed},
                 {"p_peak_computed", h.p_peak_computed},
                 {"rms_error_over_p0", h.rms_error_over_p0}};
  if (large)
    out.figures["reference_frame"] = {{"a_computed", reference.a_computed},
                                      {"rms_error_over_p0", reference.rms_error_over_p0}};
  char line[256];
  std::snprintf(line, sizeof line,
                "Hertz: p_peak %.4g MPa (analytic p0 %.4g MPa, %+.2f%%), a %.3f mm (analytic %.3f mm), "
                "RMS error %.2f%% of p0, load %.6g N",
                h.p_peak_computed / 1e6, h.p0_analytic / 1e6, 100 * (h.p_peak_computed / h.p0_analytic - 1),
                1e3 * h.a_computed, 1e3 * h.a_analytic, 100 * h.rms_error_over_p0, applied_load);
  out.summary_line = line;
  return out;
}
} // namespace feticon::problems
