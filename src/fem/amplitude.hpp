#pragma once
/// @file A tabular amplitude (deck *AMPLITUDE, a problem file's `amplitude:`): the factor a
/// load or a prescribed displacement is multiplied with at time t.

#include <string>
#include <utility>
#include <vector>

namespace feticon::fem
{
/// a(t) piecewise linear through (time, value) points, the first value before the first time
/// and the last after the last (CalculiX's and Abaqus's rule), at t - shift_x, plus shift_y.
struct Amplitude
{
  std::vector<std::pair<double, double>> points; ///< (time, value), times non-decreasing
  /// The time of the history (true: TIME=TOTAL TIME) or of the step (false, the default).
  bool total_time = false;
  double shift_x = 0;     ///< SHIFTX: the table starts this much later
  double shift_y = 0;     ///< SHIFTY: added to every value
  std::string where = {}; ///< for messages: the deck line or the file key

  double value(double t) const;
  /// Throws feticon::Error naming `where` for fewer than two points, times that decrease or a
  /// value or shift that is not finite.
  void check() const;
};
} // namespace feticon::fem
