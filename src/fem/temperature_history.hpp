#pragma once
/// @file The temperature of every node over a problem's steps, and the change T - T_0 from the
/// initial temperature that the thermal strain alpha (T - T_0) I of the elements counts from.
///
/// CalculiX's rule (tempload.f): in step s a node with a temperature T_s and no amplitude goes
/// linearly from its temperature at the end of step s - 1 (T_0 in step 1) to T_s,
///   T = T_{s-1} + fraction (T_s - T_{s-1})   (T_s at once with ramp = false),
/// a node with an amplitude is T_s a(t), and a node that step s does not name goes to its T_0
/// by the same ramp. The thermal strain is additive on the strain of the kinematics, small
/// strain or Green-Lagrange E (fem/hex8_element.hpp), as in CalculiX: S = C : (E - alpha (T -
/// T_0) I). With constant alpha, CalculiX's alpha (T - T_ref) - alpha (T_0 - T_ref) (T_ref its
/// ZERO=) is that strain whatever T_ref, so no reference temperature is kept.

#include "fem/load_history.hpp"
#include "fem/problem.hpp"
#include "la/types.hpp"

#include <vector>

namespace feticon::fem
{
class TemperatureHistory
{
public:
  /// @brief The temperatures of `problem`'s steps (validated: nodes in range, amplitudes defined).
  explicit TemperatureHistory(const Problem& problem);

  /// No step gives a temperature: no thermal strain anywhere.
  bool empty() const { return _stages.empty(); }
  /// T - T_0 per mesh node at `point` (its stage, fraction and total time); empty if empty().
  la::Vector change(const LoadPoint& point) const;

private:
  /// One step's temperatures: the start (the end of the step before) and, per node, the target
  /// and the amplitude (-1: the ramp).
  struct Stage
  {
    la::Vector start, target;
    std::vector<int> amplitude;
    double period = 1;
    bool ramp = true;
  };
  la::Vector at(const Stage& stage, double fraction, double total_time) const;

  la::Vector _initial;
  std::vector<Amplitude> _amplitudes;
  std::vector<Stage> _stages;
};
} // namespace feticon::fem
