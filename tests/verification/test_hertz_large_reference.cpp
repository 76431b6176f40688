/// Hertz with large displacements against a reference that shares none of feticon's element,
/// contact rows or solver (issue 17): CalculiX 2.20's NLGEOM solution with penalty contact on
/// the same problem meshed twice as finely (240 slave elements across 2a), stored with its
/// provenance in tests/data/hertz_large_calculix_240.csv.
///
/// Measure: RMS over 400 points of [0, a] of the difference of the two pressure profiles, each
/// interpolated linearly at the deformed coordinate x + u_x, over p0 (a = 68.08 mm,
/// p0 = 3 741 MPa, McEwen). Measured for feticon (default settings): 0.63 / 0.54 / 0.35 % at
/// 60 / 120 / 240 elements across 2a, falling under refinement. Asserted at 120: below 0.7 %.
/// Wrong answers measured against the same reference: the small-displacement solution 2.4 %,
/// the large-displacement one under a 3 % larger load 2.5 %, the right one compared at the
/// reference x instead of the deformed one 0.83 %; all fail the bound.

#include "nonlinear/contact_pressure.hpp"
#include "nonlinear/feti_contact_solver.hpp"
#include "problems/hertz.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

using namespace feticon;

namespace
{
using Profile = std::vector<std::pair<double, double>>; ///< (deformed x, pressure), sorted

Profile read_reference()
{
  std::ifstream in(std::string(FETICON_SOURCE_DIR) + "/tests/data/hertz_large_calculix_240.csv");
  EXPECT_TRUE(in.good()) << "tests/data/hertz_large_calculix_240.csv is missing";
  Profile out;
  std::string line;
  while (std::getline(in, line))
  {
    if (line.empty() || line[0] == '#' || line[0] == 'x')
      continue;
    std::istringstream fields(line);
    std::string x, x_deformed, p;
    std::getline(fields, x, ',');
    std::getline(fields, x_deformed, ',');
    std::getline(fields, p, ',');
    out.push_back({std::stod(x_deformed), std::stod(p)});
  }
  std::sort(out.begin(), out.end());
  return out;
}

/// Linear interpolation, written here again so that the comparison does not rest on
/// problems::compare_with_hertz.
double interpolate(const Profile& profile, double x)
{
  if (x <= profile.front().first)
    return profile.front().second;
  for (size_t i = 0; i + 1 < profile.size(); ++i)
    if (x <= profile[i + 1].first)
    {
      const auto [x0, p0] = profile[i];
      const auto [x1, p1] = profile[i + 1];
      return x1 > x0 ? p0 + (p1 - p0) * (x - x0) / (x1 - x0) : p0;
    }
  return 0.0;
}
} // namespace

TEST(HertzLargeDisplacements, AgreesWithAFinerCalculixSolution)
{
  const Profile reference = read_reference();
  ASSERT_GT(reference.size(), 100u);

  problems::HertzParameters parameters;
  parameters.mesh.refinement = 120 / 27.2312; // 120 slave elements across 2a
  const fem::Problem problem = problems::hertz_problem(parameters);
  nonlinear::SolverSettings s;
  s.kinematics = fem::Kinematics::total_lagrangian;
  s.load_steps = 2;
  s.dual.preconditioner = dual::DualPreconditioner::dirichlet;
  TimerTable timers;
  const auto solution = nonlinear::solve_feti_contact(problem, s, timers);
  ASSERT_TRUE(solution.converged) << solution.reason;

  Profile computed;
  for (const auto& sample : nonlinear::slave_pressure_by_x(problem, solution, s.kinematics))
    computed.push_back({sample.deformed_x, sample.pressure});
  std::sort(computed.begin(), computed.end());

  const problems::HertzAnalytic hertz = problems::hertz_analytic(parameters);
  constexpr int points = 400;
  double sum = 0;
  for (int k = 0; k < points; ++k)
  {
    const double x = hertz.half_width * (k + 0.5) / points;
    const double d = interpolate(computed, x) - interpolate(reference, x);
    sum += d * d;
  }
  const double rms = std::sqrt(sum / points) / hertz.peak_pressure;
  std::printf("RMS difference from CalculiX at 240 elements across 2a: %.3f %% of p0\n", 100 * rms);
  EXPECT_LT(rms, 0.007);
  EXPECT_NEAR(nonlinear::total_normal_force(solution), 0.5 * parameters.line_load * parameters.mesh.thickness,
              1e-3 * 0.5 * parameters.line_load * parameters.mesh.thickness);
}
