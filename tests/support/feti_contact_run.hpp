#pragma once
/// @file One FETI contact solve and the figures the verification tests compare: the solution,
/// its peak nodal contact pressure and the MPRGP steps over all outer iterations. The solve
/// must converge (a gtest failure otherwise).

#include "common/timer.hpp"
#include "nonlinear/contact_pressure.hpp"
#include "nonlinear/feti_contact_solver.hpp"

#include <gtest/gtest.h>

#include <algorithm>

namespace feticon::test
{
struct FetiContactRun
{
  nonlinear::ContactSolution solution;
  double peak = 0; ///< largest nodal contact pressure (Pa)
  int mprgp = 0;   ///< MPRGP steps of every QP of the run
};

inline FetiContactRun run_feti_contact(const fem::Problem& problem, const nonlinear::SolverSettings& settings)
{
  TimerTable timers;
  FetiContactRun out{nonlinear::solve_feti_contact(problem, settings, timers)};
  EXPECT_TRUE(out.solution.converged) << out.solution.reason;
  for (const auto& sample : nonlinear::slave_pressure_by_x(problem, out.solution, settings.kinematics))
    out.peak = std::max(out.peak, sample.pressure);
  for (const auto& it : out.solution.history)
    out.mprgp += it.qp.iterations;
  return out;
}
} // namespace feticon::test
