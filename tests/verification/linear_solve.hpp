#pragma once
/// The linear (small-displacement) FETI solve of the verification tests of 2D solids, to a
/// tight QP tolerance (qp.rtol alone, no force criterion): answers to round-off.

#include "nonlinear/feti_contact_solver.hpp"

namespace feticon::test
{
inline nonlinear::ContactSolution solve_linear(const fem::Problem& problem, int subdomains, double rtol)
{
  nonlinear::SolverSettings settings;
  settings.kinematics = fem::Kinematics::linear;
  settings.dual.rtol = rtol;
  settings.dual.force_rtol = 0;
  settings.subdomains = subdomains;
  TimerTable timers;
  return nonlinear::solve_feti_contact(problem, settings, timers);
}
} // namespace feticon::test
