/// Finite-rotation contact (issue 5): a cantilever bent by tens of degrees onto an obstacle.
/// Reference: the independent undecomposed primal penalty solve with full Newton (consistent
/// tangent, CHOLMOD, consistent active set per step) on the same mesh; FETI uses the modified
/// Newton loop with K_M(u) refreshed every iteration.

#include "nonlinear/contact_pressure.hpp"
#include "nonlinear/feti_contact_solver.hpp"
#include "nonlinear/primal_penalty_solver.hpp"
#include "problems/cantilever_obstacle.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace feticon;

namespace
{
/// Mean displacement of the beam's free-end nodes.
Eigen::Vector3d tip_displacement(const fem::Problem& p, const la::Vector& u)
{
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  const auto& nodes = p.mesh.node_set("beam_xmax");
  for (int32_t n : nodes)
    sum += u.segment<3>(3 * n);
  return sum / static_cast<double>(nodes.size());
}

/// Rotation of the free end (clockwise positive, i.e. bending down): angle of the chord from
/// the mean of the end face's bottom edge to the mean of its top edge.
double tip_rotation(const fem::Problem& p, const la::Vector& u, double depth)
{
  Eigen::Vector3d bottom = Eigen::Vector3d::Zero(), top = Eigen::Vector3d::Zero();
  for (int32_t n : p.mesh.node_set("beam_xmax"))
  {
    const Eigen::Vector3d x = p.mesh.nodes.row(n).transpose() + u.segment<3>(3 * n);
    if (p.mesh.nodes(n, 1) < 1e-12)
      bottom += x;
    else if (p.mesh.nodes(n, 1) > depth - 1e-12)
      top += x;
  }
  const Eigen::Vector3d chord = top - bottom; // both edges have the same node count
  return std::atan2(chord(0), chord(1));
}

nonlinear::SolverSettings settings(fem::Kinematics kinematics, nonlinear::ContactMethod method)
{
  nonlinear::SolverSettings s;
  s.method = method;
  s.kinematics = kinematics;
  s.load_steps = kinematics == fem::Kinematics::linear ? 1 : 10;
  s.dual.preconditioner = dual::DualPreconditioner::none;
  // Contact rows for the whole gap in the reference configuration too (the automatic
  // distance, one master element, would see no contact in the linear run).
  s.search_distance = 0.5;
  s.max_outer_iterations = 60;
  s.displacement_tolerance = 1e-8;
  s.subdomains = 4;
  s.dual.rtol = 1e-9;
  s.eps_n_factor = 1e3;
  s.stiffness = nonlinear::StiffnessUpdate::iteration;
  return s;
}
} // namespace

// Tolerances: the penalty reference differs from the exact-multiplier solution by the
// penetration lambda/eps_n (eps_n = 1e3 max diag K: ~1e-7 of the displacement) and both
// loops stop at |du|/|u| <= 1e-8, so 1e-4 relative on the tip displacement and 1e-3 on the
// contact force are stated with a wide margin over those errors.
TEST(FiniteRotationContact, FetiMatchesUndecomposedPenaltyAndLinearKinematicsFails)
{
  const problems::CantileverObstacleParameters parameters;
  const fem::Problem problem = problems::cantilever_obstacle_problem(parameters);
  TimerTable timers;
  const auto feti = nonlinear::solve_feti_contact(
      problem, settings(fem::Kinematics::total_lagrangian, nonlinear::ContactMethod::smalbe), timers);
  ASSERT_TRUE(feti.converged) << feti.reason;
  const auto penalty = nonlinear::solve_primal_penalty(
      problem, settings(fem::Kinematics::total_lagrangian, nonlinear::ContactMethod::primal_penalty), timers);
  ASSERT_TRUE(penalty.converged) << penalty.reason;
  const auto linear = nonlinear::solve_feti_contact(
      problem, settings(fem::Kinematics::linear, nonlinear::ContactMethod::smalbe), timers);
  ASSERT_TRUE(linear.converged) << linear.reason;

  const Eigen::Vector3d w_feti = tip_displacement(problem, feti.u);
  const Eigen::Vector3d w_pen = tip_displacement(problem, penalty.u);
  const Eigen::Vector3d w_lin = tip_displacement(problem, linear.u);
  const double F_feti = nonlinear::total_normal_force(feti);
  const double F_pen = nonlinear::total_normal_force(penalty);
  const double F_lin = nonlinear::total_normal_force(linear);
  int outer = 0;
  for (const auto& s : feti.steps)
    outer += s.outer_iterations;
  std::printf("tip displacement (x, y) m / rotation deg / contact force N:\n"
              "  FETI TL      (%.6f, %.6f) %6.2f %.6e  (%d outer iterations in %zu steps)\n"
              "  penalty TL   (%.6f, %.6f) %6.2f %.6e\n"
              "  FETI linear  (%.6f, %.6f) %6.2f %.6e\n",
              w_feti(0), w_feti(1), tip_rotation(problem, feti.u, parameters.depth) * 180 / M_PI, F_feti, outer,
              feti.steps.size(), w_pen(0), w_pen(1), tip_rotation(problem, penalty.u, parameters.depth) * 180 / M_PI,
              F_pen, w_lin(0), w_lin(1), tip_rotation(problem, linear.u, parameters.depth) * 180 / M_PI, F_lin);
  EXPECT_GT(std::abs(tip_rotation(problem, feti.u, parameters.depth)), 20 * M_PI / 180) << "not a finite rotation";
  EXPECT_LT((w_feti - w_pen).norm() / w_pen.norm(), 1e-4);
  EXPECT_LT(std::abs(F_feti - F_pen) / F_pen, 1e-3);
  // Small-displacement kinematics misses the shortening and the rotated contact geometry.
  EXPECT_GT((w_lin - w_pen).norm() / w_pen.norm(), 0.1);
}
