/// Load histories of several stages (fem/load_history.hpp) through the contact solvers: the
/// answer at each stage's end against one-stage runs of the same final load (frictionless
/// contact of elastic bodies is path independent), a stage that changes prescribed
/// displacements against uniaxial stress, the restart of a run at a later stage, and the
/// load factors the solutions carry (CalculiX's total time).

#include "contact_test_problems.hpp"
#include "common/error.hpp"
#include "fem/assembler.hpp"
#include "mesh/box.hpp"
#include "nonlinear/contact_pressure.hpp"
#include "nonlinear/direct_newton.hpp"
#include "nonlinear/feti_contact_solver.hpp"
#include "nonlinear/primal_penalty_solver.hpp"
#include "problems/cantilever_obstacle.hpp"
#include "problems/hertz.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

using namespace feticon;

namespace
{
/// u and the slave pressures of a solution (at a load step's end, or the run's end).
struct StageAnswer
{
  la::Vector u;
  std::vector<double> pressure; ///< by slave node line, sorted by x
  double force = 0;             ///< total normal contact force (N)
  double load_factor = 0;
};

StageAnswer answer(const fem::Problem& problem, const nonlinear::ContactSolution& solution, fem::Kinematics kinematics)
{
  StageAnswer out{solution.u,
                  {},
                  nonlinear::total_normal_force(solution),
                  solution.steps.empty() ? 0.0 : solution.steps.back().load_factor};
  for (const auto& sample : nonlinear::slave_pressure_by_x(problem, solution, kinematics))
    out.pressure.push_back(sample.pressure);
  return out;
}

/// Every converged load step's answer, by step.
struct Recorder
{
  const fem::Problem& problem;
  fem::Kinematics kinematics;
  std::map<int, StageAnswer> steps;
  std::map<int, nonlinear::ContactSolution> solutions; ///< kept when `keep_solutions`
  bool keep_solutions = false;
  nonlinear::StepCallback callback()
  {
    return [this](int step, const nonlinear::ContactSolution& s) {
      steps[step] = answer(problem, s, kinematics);
      if (keep_solutions)
        solutions[step] = s;
    };
  }
};

/// max |a - b| / max |b|.
double relative_difference(const la::Vector& a, const la::Vector& b)
{
  return (a - b).lpNorm<Eigen::Infinity>() / b.lpNorm<Eigen::Infinity>();
}

/// max |p_a - p_b| / scale over the samples (the same mesh and rows: the same samples).
double pressure_difference(const std::vector<double>& a, const std::vector<double>& b, double scale)
{
  EXPECT_EQ(a.size(), b.size());
  double d = 0;
  for (size_t i = 0; i < std::min(a.size(), b.size()); ++i)
    d = std::max(d, std::abs(a[i] - b[i]) / scale);
  return d;
}

/// The problem's first step with its load (tractions) scaled, in `increments`.
fem::Step scaled_stage(const fem::Problem& problem, double factor, int increments)
{
  fem::Step stage = problem.steps.front();
  for (fem::FaceTraction& t : stage.tractions)
    t.traction *= factor;
  stage.increments = increments;
  return stage;
}

nonlinear::SolverSettings small_displacements(nonlinear::ContactMethod method)
{
  nonlinear::SolverSettings s;
  s.kinematics = fem::Kinematics::linear;
  s.method = method;
  s.dual.method = dual::DualMethod::smalbe;
  s.subdomains = 4;
  s.dual.rtol = 1e-10;
  s.dual.force_rtol = 0; // qp.rtol alone: the runs are compared to 1e-9
  return s;
}

problems::HertzParameters coarse_hertz(double line_load)
{
  problems::HertzParameters parameters;
  parameters.mesh.refinement = 0.5; // test time; the contact zone still spans several nodes
  parameters.line_load = line_load;
  return parameters;
}

/// Hertz (refinement 0.5, small displacements) with stage 1 at Q and stage 2 at 2Q, and the
/// one-stage runs at Q and 2Q, by `method`. The contact zone grows from stage 1 to stage 2
/// (a ~ sqrt(Q)), so the answer is not a multiple of stage 1's.
struct HertzStages
{
  StageAnswer stage1, stage2, reference1, reference2;
  nonlinear::ContactSolution staged;
  double p0 = 0; ///< McEwen's peak pressure at 2Q (Pa), the pressure scale
};

HertzStages hertz_stages(nonlinear::ContactMethod method)
{
  const double Q = 2.0e8;
  fem::Problem problem = problems::hertz_problem(coarse_hertz(Q));
  problem.steps.push_back(scaled_stage(problem, 2.0, 3)); // 3 increments: one load step regardless
  const nonlinear::SolverSettings s = small_displacements(method);
  EXPECT_EQ(s.steps(problem), 2);
  auto solve = [&](const fem::Problem& p, const nonlinear::StepCallback& on_step) {
    TimerTable timers;
    nonlinear::ContactSolution solution = method == nonlinear::ContactMethod::primal_penalty
        ? nonlinear::solve_primal_penalty(p, s, timers, on_step)
        : nonlinear::solve_feti_contact(p, s, timers, on_step);
    EXPECT_TRUE(solution.converged) << solution.reason;
    return solution;
  };
  Recorder recorder{problem, s.kinematics, {}, {}};
  HertzStages out;
  out.staged = solve(problem, recorder.callback());
  out.stage1 = recorder.steps[1];
  out.stage2 = recorder.steps[2];
  out.reference1 = answer(problem, solve(problems::hertz_problem(coarse_hertz(Q)), {}), s.kinematics);
  const fem::Problem doubled = problems::hertz_problem(coarse_hertz(2 * Q));
  out.reference2 = answer(doubled, solve(doubled, {}), s.kinematics);
  out.p0 = problems::hertz_analytic(coarse_hertz(2 * Q)).peak_pressure;
  return out;
}

void print(const char* what, const HertzStages& r)
{
  std::printf("%s: stage 1 against Q: |du|/|u| %.2e, |dp|/p0 %.2e; stage 2 against 2Q: |du|/|u| %.2e, "
              "|dp|/p0 %.2e; forces %.6e / %.6e N (stage 2 / 2Q)\n",
              what, relative_difference(r.stage1.u, r.reference1.u),
              pressure_difference(r.stage1.pressure, r.reference1.pressure, r.p0),
              relative_difference(r.stage2.u, r.reference2.u),
              pressure_difference(r.stage2.pressure, r.reference2.pressure, r.p0), r.stage2.force, r.reference2.force);
}
} // namespace

// Reference: one-stage FETI runs of the same mesh at Q and 2Q. Small displacements and
// frictionless contact: each QP's solution depends only on the load at its stage's end, so
// the stages agree with them to the QP tolerance (rtol 1e-10 on the projected gradient,
// relative to ||b||; asserted 1e-9, a factor 10 for the conditioning of the dual that takes
// the QP error to u). Measured: stage 1 identical (the same arithmetic as the one-stage run),
// stage 2 1.4e-11 in u and 3.5e-11 p0 in the pressures.
TEST(LoadStages, SmallDisplacementStagesMatchOneStageRunsFeti)
{
  const HertzStages r = hertz_stages(nonlinear::ContactMethod::smalbe);
  print("FETI", r);
  ASSERT_EQ(r.staged.steps.size(), 2u);
  EXPECT_EQ(r.staged.steps[0].load_factor, 1.0);
  EXPECT_EQ(r.staged.steps[1].load_factor, 2.0);
  EXPECT_EQ(r.stage1.load_factor, 1.0);
  EXPECT_LT(relative_difference(r.stage1.u, r.reference1.u), 1e-9);
  EXPECT_LT(relative_difference(r.stage2.u, r.reference2.u), 1e-9);
  EXPECT_LT(pressure_difference(r.stage1.pressure, r.reference1.pressure, r.p0), 1e-9);
  EXPECT_LT(pressure_difference(r.stage2.pressure, r.reference2.pressure, r.p0), 1e-9);
  EXPECT_NEAR(r.stage2.force, r.reference2.force, 1e-9 * r.reference2.force);
  // Not a multiple of stage 1: the contact zone grew (the test would not see a stage that
  // only scaled the first answer).
  EXPECT_GT(relative_difference(r.stage2.u, 2 * r.stage1.u), 1e-3);
}

// Reference: one-stage primal penalty runs at Q and 2Q. Each stage ends with the penalized
// system of a consistent active set, the same linear system as the one-stage run's: equal to
// round-off of the CHOLMOD solves (asserted 1e-9; measured: identical, the stage ends' loads
// being the one-stage loads bit for bit).
TEST(LoadStages, SmallDisplacementStagesMatchOneStageRunsPrimalPenalty)
{
  const HertzStages r = hertz_stages(nonlinear::ContactMethod::primal_penalty);
  print("primal penalty", r);
  ASSERT_EQ(r.staged.steps.size(), 2u);
  EXPECT_EQ(r.staged.steps[1].load_factor, 2.0);
  EXPECT_LT(relative_difference(r.stage1.u, r.reference1.u), 1e-9);
  EXPECT_LT(relative_difference(r.stage2.u, r.reference2.u), 1e-9);
  EXPECT_LT(pressure_difference(r.stage2.pressure, r.reference2.pressure, r.p0), 1e-9);
}

// Reference: one-step FETI runs of the same mesh at the amplitude's levels. The line load of
// Hertz follows a tabular amplitude up and down within one step, (0, 0), (0.5, 1), (1, 0.4), in
// 4 increments (levels 0.5, 1, 0.7, 0.4 of Q); small displacements and frictionless contact
// are path independent, so each increment's answer is the static answer at its level to the
// QP tolerance (rtol 1e-10; asserted 1e-8, issue 65's bar). The unloading increments (0.7 and
// 0.4 after 1) are what a ramp could not give.
TEST(LoadStages, AmplitudeUpAndDownMatchesStaticLoadsAtEachLevel)
{
  const double Q = 2.0e8;
  fem::Problem problem = problems::hertz_problem(coarse_hertz(Q));
  problem.amplitudes["UPDOWN"] = {{{0.0, 0.0}, {0.5, 1.0}, {1.0, 0.4}}};
  problem.steps.front().tractions[0].amplitude = "UPDOWN";
  problem.steps.front().increments = 4;
  const nonlinear::SolverSettings s = small_displacements(nonlinear::ContactMethod::smalbe);
  ASSERT_EQ(s.steps(problem), 4);
  Recorder recorder{problem, s.kinematics, {}, {}};
  TimerTable timers;
  const nonlinear::ContactSolution run = nonlinear::solve_feti_contact(problem, s, timers, recorder.callback());
  ASSERT_TRUE(run.converged) << run.reason;
  const std::vector<double> levels = {0.5, 1.0, 0.7, 0.4};
  for (int n = 1; n <= 4; ++n)
  {
    const fem::Problem level = problems::hertz_problem(coarse_hertz(levels[n - 1] * Q));
    const nonlinear::ContactSolution reference = nonlinear::solve_feti_contact(level, s, timers);
    ASSERT_TRUE(reference.converged) << reference.reason;
    const StageAnswer expected = answer(level, reference, s.kinematics);
    const double p0 = problems::hertz_analytic(coarse_hertz(levels[n - 1] * Q)).peak_pressure;
    const double du = relative_difference(recorder.steps[n].u, expected.u);
    const double dp = pressure_difference(recorder.steps[n].pressure, expected.pressure, p0);
    std::printf("increment %d (a = %.2f): |du|/|u| %.2e, |dp|/p0 %.2e, force %.9e / %.9e N\n", n, levels[n - 1], du, dp,
                recorder.steps[n].force, expected.force);
    EXPECT_LT(du, 1e-8);
    EXPECT_LT(dp, 1e-8);
    EXPECT_NEAR(recorder.steps[n].force, expected.force, 1e-8 * expected.force);
  }
}

namespace
{
/// Pressed blocks (3x3 matching contact faces, no gap) with the upper block's top pushed by a
/// prescribed u_z = d[0] in stage 1, d[1], d[2], ... in the later stages; no load.
fem::Problem pushed_blocks(const std::vector<double>& d)
{
  fem::Problem problem = test::pressed_blocks(3, 3, 0.0, 0.0);
  problem.steps.front().tractions.clear();
  auto supports = [&](double top) {
    std::vector<fem::DirichletCondition> conditions = problem.steps.front().dirichlet;
    conditions.push_back({"upper_zmax", {std::nullopt, std::nullopt, top}});
    return conditions;
  };
  const std::vector<fem::DirichletCondition> first = supports(d[0]);
  for (size_t k = 1; k < d.size(); ++k)
  {
    fem::Step stage;
    stage.dirichlet = supports(d[k]);
    stage.increments = 1;
    problem.steps.push_back(stage);
  }
  problem.steps.front().dirichlet = first;
  problem.validate();
  return problem;
}
} // namespace

// Reference: uniaxial stress. Two unit blocks in series (E = 2e11 Pa, rollers on the xmin and
// ymin faces, lateral faces free) under a top displacement d < 0 carry the contact pressure
// E |d| / 2 over the unit contact face; for d > 0 the contact opens: no force, the lower block
// at rest and the upper one translated by d. The FE space holds these fields, so the stages
// (d = -2e-4, -1e-4, +1e-4) reproduce them to the QP tolerance (rtol 1e-10; asserted 1e-8
// relative to the first stage's force and displacement, a factor 100 for the conditioning).
// Measured: pressures within 1.6e-11 and 2.4e-11, stage 3's u within 3.9e-11.
TEST(LoadStages, AStageChangesAPrescribedDisplacement)
{
  const double E = 2e11;
  const std::vector<double> d = {-2e-4, -1e-4, 1e-4};
  const fem::Problem problem = pushed_blocks(d);
  const nonlinear::SolverSettings s = small_displacements(nonlinear::ContactMethod::smalbe);
  Recorder recorder{problem, s.kinematics, {}, {}};
  TimerTable timers;
  const nonlinear::ContactSolution solution = nonlinear::solve_feti_contact(problem, s, timers, recorder.callback());
  ASSERT_TRUE(solution.converged) << solution.reason;
  ASSERT_EQ(recorder.steps.size(), 3u);
  const double force_scale = E * 2e-4 / 2;
  for (int step = 1; step <= 3; ++step)
  {
    const StageAnswer& a = recorder.steps[step];
    const double expected = d[step - 1] < 0 ? E * -d[step - 1] / 2 : 0.0;
    double pressure_error = 0;
    for (double p : a.pressure)
      pressure_error = std::max(pressure_error, std::abs(p - expected) / force_scale);
    std::printf("stage %d (t = %g): d = %.1e m, contact force %.9e N (uniaxial stress: %.9e), "
                "max |p - p_exact| / p_1 %.1e\n",
                step, a.load_factor, d[step - 1], a.force, expected, pressure_error);
    EXPECT_EQ(a.load_factor, step);
    EXPECT_NEAR(a.force, expected, 1e-8 * force_scale);
    EXPECT_LT(pressure_error, 1e-8);
  }
  // Stage 3: open contact, lower block at rest, upper block translated by d.
  const la::Vector& u = recorder.steps[3].u;
  const int32_t n_lower = 4 * 4 * 4; // the upper block's nodes follow the lower's (append_mesh)
  la::Vector exact = la::Vector::Zero(u.size());
  for (int32_t n = n_lower; n < problem.mesh.n_nodes(); ++n)
    exact(3 * n + 2) = d[2];
  std::printf("stage 3: max |u - u_exact| / |d| %.1e\n", relative_difference(u, exact));
  EXPECT_LT(relative_difference(u, exact), 1e-8);
}

// Reference: the uninterrupted run. A run restarted from the state after stage 1 (the
// checkpoint's RestartState, kept in memory here) continues with stage 2 and ends where the
// uninterrupted run ends, to the QP tolerance (rtol 1e-10; asserted 1e-8; measured: identical,
// the restored state being the uninterrupted run's). A restart whose
// step numbers name other load factors (other load_steps) is refused.
TEST(LoadStages, RestartContinuesAtTheNextStage)
{
  const std::vector<double> d = {-2e-4, -1e-4, 1e-4};
  const fem::Problem problem = pushed_blocks(d);
  nonlinear::SolverSettings s = small_displacements(nonlinear::ContactMethod::smalbe);
  Recorder recorder{problem, s.kinematics, {}, {}, true};
  TimerTable timers;
  const nonlinear::ContactSolution full = nonlinear::solve_feti_contact(problem, s, timers, recorder.callback());
  ASSERT_TRUE(full.converged) << full.reason;
  const nonlinear::ContactSolution& after_stage_1 = recorder.solutions.at(1);
  ASSERT_EQ(after_stage_1.restart.completed_steps, 1);

  Recorder restarted_steps{problem, s.kinematics, {}, {}};
  const nonlinear::ContactSolution restarted =
      nonlinear::solve_feti_contact(problem, s, timers, restarted_steps.callback(), &after_stage_1);
  ASSERT_TRUE(restarted.converged) << restarted.reason;
  EXPECT_EQ(restarted_steps.steps.count(1), 0u); // stage 1 is not solved again
  ASSERT_EQ(restarted.steps.size(), 3u);
  EXPECT_EQ(restarted.steps[1].load_factor, 2.0);
  EXPECT_EQ(restarted.steps[2].load_factor, 3.0);
  for (int step : {2, 3})
  {
    const double difference = relative_difference(restarted_steps.steps[step].u, recorder.steps[step].u);
    std::printf("restarted step %d against the uninterrupted run: |du|/|u| %.1e\n", step, difference);
    EXPECT_LT(difference, 1e-8);
  }

  // Large displacements in 2 load steps per stage: step 1 is at t = 0.5, the checkpoint's at 1.
  s.kinematics = fem::Kinematics::total_lagrangian;
  s.load_steps = 2;
  EXPECT_EQ(s.steps(problem), 4);
  try
  {
    nonlinear::solve_feti_contact(problem, s, timers, {}, &after_stage_1);
    ADD_FAILURE() << "a checkpoint of another load history was accepted";
  }
  catch (const Error& e)
  {
    EXPECT_NE(std::string(e.what()).find("at load factor 1, this run's at 0.5"), std::string::npos) << e.what();
  }
}

namespace
{
nonlinear::SolverSettings cantilever_settings(int load_steps)
{
  nonlinear::SolverSettings s;
  s.method = nonlinear::ContactMethod::smalbe;
  s.kinematics = fem::Kinematics::total_lagrangian;
  s.load_steps = load_steps;
  s.dual.preconditioner = dual::DualPreconditioner::none;
  s.search_distance = 0.5;
  s.max_outer_iterations = 60;
  s.displacement_tolerance = 1e-8;
  s.subdomains = 4;
  s.dual.rtol = 1e-9;
  s.stiffness = nonlinear::StiffnessUpdate::iteration;
  return s;
}
} // namespace

// Reference: the one-stage run of the same final load P in 10 load steps. Frictionless contact
// of an elastic body is path independent (the equilibrium minimizes the potential energy,
// unique here), so two stages that overshoot (1.2 P in 8 load steps, then back to P in 2: the
// contact zone grows past its final size and recedes) reach the same configuration to the
// Newton tolerance (|du|/|u| <= 1e-8 per run, QPs at 1e-9; asserted 1e-7 relative on u, a
// factor 10 for the outer loop's linear rate, and 1e-6 on the contact force, the multipliers
// being the less accurate output of an outer loop that stops on |du|). Measured: 1.6e-11 in u,
// 2.2e-10 in the force, 55 outer iterations against 58.
TEST(LoadStages, LargeDisplacementStagesMatchAOneStageRun)
{
  problems::CantileverObstacleParameters parameters;
  parameters.cells_along = 20;
  fem::Problem staged = problems::cantilever_obstacle_problem(parameters);
  const fem::Problem one_stage = staged;
  staged.steps.push_back(scaled_stage(staged, 1.0, 2));
  staged.steps.front().tractions[0].traction *= 1.2;
  TimerTable timers;
  const nonlinear::SolverSettings s = cantilever_settings(8);
  EXPECT_EQ(s.steps(staged), 10);
  const nonlinear::ContactSolution two = nonlinear::solve_feti_contact(staged, s, timers);
  ASSERT_TRUE(two.converged) << two.reason;
  const nonlinear::ContactSolution one = nonlinear::solve_feti_contact(one_stage, cantilever_settings(10), timers);
  ASSERT_TRUE(one.converged) << one.reason;
  ASSERT_EQ(two.steps.size(), 10u);
  EXPECT_DOUBLE_EQ(two.steps[7].load_factor, 1.0);
  EXPECT_DOUBLE_EQ(two.steps[8].load_factor, 1.5);
  EXPECT_DOUBLE_EQ(two.steps[9].load_factor, 2.0);
  const double du = relative_difference(two.u, one.u);
  const double F_two = nonlinear::total_normal_force(two), F_one = nonlinear::total_normal_force(one);
  int outer_two = 0, outer_one = 0;
  for (const auto& st : two.steps)
    outer_two += st.outer_iterations;
  for (const auto& st : one.steps)
    outer_one += st.outer_iterations;
  std::printf("two stages against one: |du|/|u| %.2e, contact force %.9e / %.9e N (%.2e), outer iterations %d / %d\n",
              du, F_two, F_one, std::abs(F_two - F_one) / F_one, outer_two, outer_one);
  EXPECT_GT(F_one, 0);
  EXPECT_LT(du, 1e-7);
  EXPECT_NEAR(F_two, F_one, 1e-6 * F_one);
}

// Reference: the direct Newton reference (no contact) on a cantilever box, one stage to the
// end load F in 3 load steps against two stages (2 F in 4 steps, back to F in 2): the same
// equilibrium of a path-independent elastic problem, to the Newton tolerance (rtol 1e-10,
// quadratic convergence: asserted 1e-9 relative; measured 5e-16). Tip deflection 0.61 m
// (P L^2 / EI = 4, stiffer than the elastica's 0.67 by the locking of two cells through the
// depth; ALGORITHMS.md section 7).
TEST(LoadStages, DirectNewtonFollowsTheHistory)
{
  fem::Problem problem;
  problem.name = "cantilever box";
  mesh::BoxParameters box;
  box.lengths = Eigen::Vector3d(1, 0.1, 0.1);
  box.nx = 10;
  box.ny = box.nz = 2;
  problem.mesh = mesh::generate_box(box);
  problem.materials = {fem::Material{2e11, 0.3}};
  problem.steps.front().dirichlet = {{"xmin", {0.0, 0.0, 0.0}}};
  const double F = 4 * 2e11 * (0.1 * 0.1 * 0.1 * 0.1 / 12); // P L^2 / EI = 4 as a traction on 0.01 m^2
  problem.steps.front().tractions = {{"xmax", Eigen::Vector3d(0, -F / 0.01, 0)}};
  problem.validate();
  fem::Problem staged = problem;
  staged.steps.push_back(scaled_stage(problem, 1.0, 2));
  staged.steps.front().tractions[0].traction *= 2;
  const fem::Assembler assembler(problem.mesh, fem::whole_mesh_domain(problem.mesh), problem.materials,
                                 fem::Kinematics::total_lagrangian);
  nonlinear::DirectNewtonOptions options;
  options.load_steps = 3;
  la::Vector u_one = la::Vector::Zero(3 * problem.mesh.n_nodes());
  const auto one =
      nonlinear::solve_direct_newton(assembler, fem::LoadHistory(problem, {.default_steps = 3}), u_one, options);
  la::Vector u_two = la::Vector::Zero(3 * problem.mesh.n_nodes());
  const fem::LoadHistory history(staged, {.default_steps = 4});
  ASSERT_EQ(history.n_steps(), 6);
  const auto two = nonlinear::solve_direct_newton(assembler, history, u_two, options);
  ASSERT_TRUE(one.converged && two.converged);
  EXPECT_EQ(two.iterations.size(), 6u);
  // The one-stage overload is the history of one stage.
  la::Vector u_plain = la::Vector::Zero(3 * problem.mesh.n_nodes());
  ASSERT_TRUE(nonlinear::solve_direct_newton(assembler, problem.all_constrained_dofs(), problem.external_force(),
                                             u_plain, options)
                  .converged);
  EXPECT_TRUE((u_plain.array() == u_one.array()).all());
  const double du = relative_difference(u_two, u_one);
  std::printf("direct Newton, two stages against one: |du|/|u| %.2e, tip deflection %.6f m\n", du, -u_one.minCoeff());
  EXPECT_GT(-u_one.minCoeff(), 0.5); // large deflection: path independence is not trivial
  EXPECT_LT(du, 1e-9);
}
