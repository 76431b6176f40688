/// Linear multi-point constraints (*EQUATION) in every solver: Total FETI (equality rows beside
/// the gluing and Dirichlet rows), the primal penalty method and the direct Newton reference
/// (elimination), with small and large displacements, checkpoint/restart and under two MPI
/// ranks (tests/cli/mpi_equations.sh runs LinearEquationsMpi under mpirun).
///
/// The problem: two unit cubes 1 mm apart (test::pressed_blocks). The lower one is clamped at
/// its base; the upper one is on rollers (u_y = 0 on its ymin face, u_z = 0 on its top face),
/// which leave it one rigid motion, sliding along x, and is pulled along x by a traction on its
/// xmax face. Only the equations hold it along x, so the whole load passes through them into
/// the lower cube. The gap stays open (the displacements are about 1e-5 m against 1e-3 m), so
/// the contact pair carries nothing and the references need no contact.

#include "common/error.hpp"
#include "contact_test_problems.hpp"
#include "decomposition/partition.hpp"
#include "fem/assembler.hpp"
#include "la/cholmod.hpp"
#include "nonlinear/direct_newton.hpp"
#include "nonlinear/feti_contact_solver.hpp"
#include "nonlinear/primal_penalty_solver.hpp"
#include "par/communicator.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <functional>
#include <map>

using namespace feticon;

namespace
{
constexpr double gap = 1e-3;

int32_t node_at(const mesh::Mesh& m, double x, double y, double z)
{
  for (int32_t n = 0; n < m.n_nodes(); ++n)
    if ((m.nodes.row(n) - Eigen::RowVector3d(x, y, z)).norm() < 1e-12)
      return n;
  ADD_FAILURE() << "no node at " << x << ", " << y << ", " << z;
  return 0;
}

/// The two cubes of the file comment, 4x4x4 cells each, with the upper one pulled by `traction` (Pa).
fem::Problem tied_blocks(double traction)
{
  fem::Problem p = test::pressed_blocks(4, 4, gap, 0.0);
  p.name = "tied blocks";
  p.steps.front().dirichlet = {{"zmin", {0.0, 0.0, 0.0}},
                               {"upper_ymin", {std::nullopt, 0.0, std::nullopt}},
                               {"upper_zmax", {std::nullopt, std::nullopt, 0.0}}};
  p.steps.front().tractions = {{"upper_xmax", Eigen::Vector3d(traction, 0, 0)}};
  return p;
}

/// Node a on the upper cube's bottom face and node b below it on the lower cube's top face, at
/// (x, y): the two nodes an equation ties.
int32_t upper_node(const fem::Problem& p, double x, double y) { return node_at(p.mesh, x, y, 1 + gap); }
int32_t lower_node(const fem::Problem& p, double x, double y) { return node_at(p.mesh, x, y, 1); }

/// Test (a): u_x(a) - u_x(b) = 0 at x = 0.5, where the structured split (2 subdomains per
/// body along x) puts both nodes on an interface.
fem::Problem one_tie()
{
  fem::Problem p = tied_blocks(1e6);
  p.equations = {{{{upper_node(p, 0.5, 0.5), 0, 1.0}, {lower_node(p, 0.5, 0.5), 0, -1.0}}}};
  return p;
}

/// Test (b): 2 u_x(a) - 3 u_x(b) + 0.5 u_y(c) = 0 and u_x(a2) - u_x(b) = 0, sharing u_x(b).
fem::Problem three_terms()
{
  fem::Problem p = tied_blocks(1e6);
  p.equations = {
      {{{upper_node(p, 0.5, 0.5), 0, 2.0}, {lower_node(p, 0.5, 0.5), 0, -3.0}, {lower_node(p, 0.75, 0.5), 1, 0.5}}},
      {{{upper_node(p, 0.25, 0.75), 0, 1.0}, {lower_node(p, 0.5, 0.5), 0, -1.0}}}};
  return p;
}

/// Reference: the direct CHOLMOD solve of the linear problem without contact, the supports
/// (all zero here) eliminated and every DOF d of `substituted` replaced by sum_j w_j u_j over
/// DOFs that are neither supported nor substituted: u = T v written out here, independently of
/// fem::ConstraintElimination (a DOF substituted by another one alone merges the two).
using Substitutions = std::map<int64_t, std::vector<std::pair<int64_t, double>>>;
la::Vector substitution_solve(const fem::Problem& p, const Substitutions& substituted)
{
  const int64_t n = 3 * static_cast<int64_t>(p.mesh.n_nodes());
  const fem::Assembler assembler(p.mesh, fem::whole_mesh_domain(p.mesh), p.materials, fem::Kinematics::linear);
  const la::SparseMatrix K = assembler.stiffness(la::Vector::Zero(n), fem::StiffnessKind::tangent);
  const fem::ConstrainedDofs supports = p.all_constrained_dofs();
  EXPECT_EQ(supports.values.cwiseAbs().maxCoeff(), 0.0);
  std::vector<int32_t> column(n, 0);
  for (const int64_t dof : supports.dofs)
    column[dof] = -1;
  for (const auto& [dof, terms] : substituted)
    column[dof] = -1;
  int32_t n_free = 0;
  for (int64_t dof = 0; dof < n; ++dof)
    if (column[dof] == 0)
      column[dof] = n_free++;
    else
      column[dof] = -1;
  std::vector<la::Triplet> triplets;
  for (int64_t dof = 0; dof < n; ++dof)
    if (column[dof] >= 0)
      triplets.emplace_back(static_cast<int>(dof), column[dof], 1.0);
  for (const auto& [dof, terms] : substituted)
    for (const auto& [j, w] : terms)
      triplets.emplace_back(static_cast<int>(dof), column[j], w);
  la::SparseMatrix T(n, n_free);
  T.setFromTriplets(triplets.begin(), triplets.end());
  const la::SparseMatrix Tt = T.transpose();
  la::CholmodFactor factor;
  factor.factorize(la::SparseMatrix(Tt * K * T));
  return T * factor.solve(la::Vector(Tt * p.external_force()));
}

nonlinear::SolverSettings feti_settings(int subdomains, nonlinear::Partitioner partitioner)
{
  nonlinear::SolverSettings s;
  s.kinematics = fem::Kinematics::linear;
  s.method = nonlinear::ContactMethod::smalbe;
  s.dual.method = dual::DualMethod::smalbe;
  s.dual.rtol = 1e-10;
  s.dual.force_rtol = 0; // qp.rtol alone: compared with elimination to 1e-9
  s.subdomains = subdomains;
  s.partitioner = partitioner;
  return s;
}

/// sum_k a_k u_k of `equation` and sum_k |a_k u_k|, its scale.
std::pair<double, double> evaluate(const fem::LinearEquation& equation, const la::Vector& u)
{
  double value = 0, scale = 0;
  for (const auto& t : equation.terms)
  {
    value += t.coefficient * u(3 * t.node + t.component);
    scale += std::abs(t.coefficient * u(3 * t.node + t.component));
  }
  return {value, scale};
}

struct Case
{
  const char* name;
  nonlinear::SolverSettings settings;
};

std::vector<Case> feti_cases()
{
  Case structured{"structured 4, implicit", feti_settings(4, nonlinear::Partitioner::structured)};
  structured.settings.dual_operator = nonlinear::DualOperatorMode::implicit;
  // The explicit operators throw if a row touches a DOF off the Schur boundary: the
  // equations' DOFs must be on it.
  Case metis{"metis 6, explicit", feti_settings(6, nonlinear::Partitioner::metis)};
  metis.settings.dual_operator = nonlinear::DualOperatorMode::explicit_;
  // Not the dual penalty method: its inactive contact rows sit on their bound, where it leaves
  // G lambda = e violated by O(1/rho) (ALGORITHMS.md 1), with or without equations.
  Case lumped{"metis 8, lumped", feti_settings(8, nonlinear::Partitioner::metis)};
  lumped.settings.dual.preconditioner = dual::DualPreconditioner::lumped;
  return {structured, metis, lumped};
}

/// Every FETI case, the primal penalty solver and the direct Newton solve against `reference`;
/// every equation evaluated on the FETI solutions.
void check_solvers(const fem::Problem& problem, const la::Vector& reference)
{
  for (const Case& c : feti_cases())
  {
    TimerTable timers;
    const nonlinear::ContactSolution solution = nonlinear::solve_feti_contact(problem, c.settings, timers);
    ASSERT_TRUE(solution.converged) << c.name << ": " << solution.reason;
    if (solution.contact_lambda.size() > 0)
    {
      EXPECT_EQ(solution.contact_lambda.cwiseAbs().maxCoeff(), 0.0) << c.name << ": the gap must stay open";
    }
    const double error = (solution.u - reference).norm() / reference.norm();
    double violation = 0;
    for (const auto& equation : problem.equations)
    {
      const auto [value, scale] = evaluate(equation, solution.u);
      violation = std::max(violation, std::abs(value) / scale);
    }
    int mprgp = 0;
    for (const auto& it : solution.history)
      mprgp += it.qp.iterations;
    std::printf("%-30s |u - u_ref|/|u_ref| = %.1e  max |sum a u|/sum |a u| = %.1e  MPRGP steps %d, dual %ld\n", c.name,
                error, violation, mprgp, static_cast<long>(solution.n_dual));
    // QP rtol 1e-10 (SMALBE-M: also ||G~ mu||): the dual error and with it the displacement
    // error and the equality rows' residual are a few orders above it at most.
    EXPECT_LT(error, 1e-8) << c.name;
    EXPECT_LT(violation, 1e-8) << c.name;
  }
  // The undecomposed solvers eliminate the equations exactly: round-off of one CHOLMOD solve.
  nonlinear::SolverSettings penalty = feti_settings(1, nonlinear::Partitioner::metis);
  penalty.method = nonlinear::ContactMethod::primal_penalty;
  TimerTable timers;
  const nonlinear::ContactSolution primal = nonlinear::solve_primal_penalty(problem, penalty, timers);
  ASSERT_TRUE(primal.converged) << primal.reason;
  const double primal_error = (primal.u - reference).norm() / reference.norm();
  const fem::Assembler assembler(problem.mesh, fem::whole_mesh_domain(problem.mesh), problem.materials,
                                 fem::Kinematics::linear);
  la::Vector u_direct = la::Vector::Zero(reference.size());
  nonlinear::DirectNewtonOptions options;
  options.equations = problem.equations;
  ASSERT_TRUE(nonlinear::solve_direct_newton(assembler, problem.all_constrained_dofs(), problem.external_force(),
                                             u_direct, options)
                  .converged);
  const double direct_error = (u_direct - reference).norm() / reference.norm();
  std::printf("primal penalty |u - u_ref|/|u_ref| = %.1e, direct Newton %.1e\n", primal_error, direct_error);
  EXPECT_LT(primal_error, 1e-11);
  EXPECT_LT(direct_error, 1e-11);
}

/// The message of the feticon::Error `f` throws ("" and a test failure if it throws none).
std::string error_of(const std::function<void()>& f)
{
  try
  {
    f();
  }
  catch (const Error& e)
  {
    return e.what();
  }
  ADD_FAILURE() << "no feticon::Error thrown";
  return "";
}
} // namespace

// Test (a). Reference: the direct solve of the same problem with u_x of the two tied nodes
// merged into one unknown (substitution_solve). Tolerance 1e-8 relative, from the QP rtol
// 1e-10 (as FetiLinear and ContactBlocks).
TEST(LinearEquations, TieBetweenBodiesMatchesMergedNodes)
{
  const fem::Problem problem = one_tie();
  const int32_t a = problem.equations[0].terms[0].node, b = problem.equations[0].terms[1].node;
  // Both tied nodes lie on an interface of the structured split: their rows go on every copy.
  const decomposition::Decomposition structured(problem.mesh,
                                                decomposition::partition_structured(problem.mesh, {2, 1, 1}));
  EXPECT_EQ(structured.copies(a).size(), 2u);
  EXPECT_EQ(structured.copies(b).size(), 2u);
  const la::Vector reference = substitution_solve(problem, {{3 * b, {{3 * a, 1.0}}}});
  // The load passes through the tie: the upper cube moves along x by about F / (E h).
  EXPECT_GT(reference(3 * a), 1e-6);
  check_solvers(problem, reference);
}

// Test (b). Reference: the direct solve with the equations eliminated by hand,
// u_x(a) = 1.5 u_x(b) - 0.25 u_y(c) and u_x(a2) = u_x(b). Tolerances as in (a); the FETI
// solution is also checked against the equations themselves, to the QP tolerance.
TEST(LinearEquations, ThreeTermsWithCoefficientsMatchElimination)
{
  const fem::Problem problem = three_terms();
  const int64_t a = 3 * problem.equations[0].terms[0].node, b = 3 * problem.equations[0].terms[1].node;
  const int64_t c_y = 3 * problem.equations[0].terms[2].node + 1, a2 = 3 * problem.equations[1].terms[0].node;
  const la::Vector reference = substitution_solve(problem, {{a, {{b, 1.5}, {c_y, -0.25}}}, {a2, {{b, 1.0}}}});
  EXPECT_GT(std::abs(reference(c_y)), 1e-3 * std::abs(reference(b))) << "the third term must matter";
  check_solvers(problem, reference);
}

// Large displacements (total Lagrangian, two load steps, K_M(u) refreshed at every outer
// iteration): the rows of a linear equation are constant, kept through the outer iterations
// and a checkpoint. Reference: the direct Newton solve with the equations eliminated (full
// Newton to |du|/|u| <= 1e-10); the FETI outer loop stops at |du|/|u| <= 1e-6 and a residual
// of 1e-6, hence 1e-5 relative. Restart: continuing from the checkpoint of load step 1 repeats
// the uninterrupted arithmetic (1e-12, as tests/cli/restart.sh); a checkpoint of a problem with
// another number of equality rows is refused.
TEST(LinearEquations, LargeDisplacementsAndRestartKeepTheRows)
{
  fem::Problem problem = three_terms();
  problem.steps.front().tractions[0].traction *= 20; // strains of about 1e-3 at the ties
  nonlinear::SolverSettings s = feti_settings(4, nonlinear::Partitioner::structured);
  s.kinematics = fem::Kinematics::total_lagrangian;
  s.load_steps = 2;
  s.stiffness = nonlinear::StiffnessUpdate::iteration;
  TimerTable timers;
  nonlinear::ContactSolution after_step_1;
  const nonlinear::ContactSolution full =
      nonlinear::solve_feti_contact(problem, s, timers, [&](int step, const nonlinear::ContactSolution& so_far) {
        if (step == 1)
          after_step_1 = so_far;
      });
  ASSERT_TRUE(full.converged) << full.reason;

  const fem::Assembler assembler(problem.mesh, fem::whole_mesh_domain(problem.mesh), problem.materials,
                                 fem::Kinematics::total_lagrangian);
  la::Vector u_direct = la::Vector::Zero(full.u.size());
  nonlinear::DirectNewtonOptions options;
  options.load_steps = 2;
  options.equations = problem.equations;
  ASSERT_TRUE(nonlinear::solve_direct_newton(assembler, problem.all_constrained_dofs(), problem.external_force(),
                                             u_direct, options)
                  .converged);
  const double error = (full.u - u_direct).norm() / u_direct.norm();
  double violation = 0;
  for (const auto& equation : problem.equations)
  {
    const auto [value, scale] = evaluate(equation, full.u);
    violation = std::max(violation, std::abs(value) / scale);
  }
  std::printf("large displacements: %zu outer iterations, |u - u_newton|/|u_newton| = %.1e, "
              "max |sum a u|/sum |a u| = %.1e, |u_x(a)| = %.2e m\n",
              full.history.size(), error, violation, std::abs(full.u(3 * problem.equations[0].terms[0].node)));
  EXPECT_LT(error, 1e-5);
  EXPECT_LT(violation, 1e-8);

  ASSERT_EQ(after_step_1.restart.completed_steps, 1);
  TimerTable restart_timers;
  const nonlinear::ContactSolution continued =
      nonlinear::solve_feti_contact(problem, s, restart_timers, {}, &after_step_1);
  ASSERT_TRUE(continued.converged) << continued.reason;
  EXPECT_LT((continued.u - full.u).norm() / full.u.norm(), 1e-12);

  fem::Problem more = problem;
  more.equations.push_back({{{upper_node(problem, 0.75, 0.25), 1, 1.0}, {lower_node(problem, 0.75, 0.25), 1, -1.0}}});
  const std::string message = error_of([&] {
    TimerTable t;
    nonlinear::solve_feti_contact(more, s, t, {}, &after_step_1);
  });
  EXPECT_NE(message.find("restart: the checkpoint holds"), std::string::npos) << message;
}

// Test (d) through the solvers: an equation that repeats another, and one on a supported DOF
// only, end the run with a message naming the equation.
TEST(LinearEquations, DegenerateEquationsStopTheSolvers)
{
  fem::Problem repeated = one_tie();
  auto twice = repeated.equations[0];
  for (auto& t : twice.terms)
    t.coefficient *= -3;
  repeated.equations.push_back(twice);
  fem::Problem supported = one_tie();
  supported.equations.push_back({{{node_at(supported.mesh, 0.5, 0.5, 0), 2, 1.0}}}); // on the clamped base
  nonlinear::SolverSettings penalty = feti_settings(1, nonlinear::Partitioner::metis);
  penalty.method = nonlinear::ContactMethod::primal_penalty;
  for (const fem::Problem* p : {&repeated, &supported})
  {
    const std::string feti = error_of([&] {
      TimerTable t;
      const auto s = feti_settings(4, nonlinear::Partitioner::metis);
      nonlinear::solve_feti_contact(*p, s, t);
    });
    const std::string primal = error_of([&] {
      TimerTable t;
      nonlinear::solve_primal_penalty(*p, penalty, t);
    });
    std::printf("%s\n", feti.c_str());
    for (const std::string& message : {feti, primal})
      EXPECT_NE(message.find("linear equation 2 of 2"), std::string::npos) << message;
  }
}

// Test (c): run by tests/cli/mpi_equations.sh as `mpirun -np 2 verification
// --gtest_filter=LinearEquationsMpi.*`; skipped when not started by an MPI launcher. Test (b)
// on 4 subdomains (structured: the lower cube's two on rank 0, the upper cube's on rank 1, so
// the equation rows touch both ranks). Reference: the same solve on one rank (Communicator::self
// in the same process), which the distributed engine matches bit for bit by design (the block
// reductions of la/vector_space.hpp; 1e-12 is asserted), and the eliminated direct solve (1e-8).
TEST(LinearEquationsMpi, TwoRanksMatchOneRank)
{
  if (!std::getenv("OMPI_COMM_WORLD_SIZE") && !std::getenv("PMIX_RANK") && !std::getenv("PMI_RANK"))
    GTEST_SKIP() << "runs under mpirun -np 2 (tests/cli/mpi_equations.sh)";
  static int argc = 0;
  static char** argv = nullptr;
  static const par::Environment environment(argc, argv); // MPI_Finalize at exit
  const par::Communicator world = par::Communicator::world();
  ASSERT_EQ(world.size(), 2);
  const fem::Problem problem = three_terms();
  const nonlinear::SolverSettings s = feti_settings(4, nonlinear::Partitioner::structured);
  TimerTable timers;
  const nonlinear::ContactSolution one =
      nonlinear::solve_feti_contact(problem, s, timers, {}, nullptr, par::Communicator::self());
  const nonlinear::ContactSolution two = nonlinear::solve_feti_contact(problem, s, timers, {}, nullptr, world);
  ASSERT_TRUE(one.converged && two.converged) << one.reason << two.reason;
  ASSERT_EQ(one.history.size(), two.history.size());
  for (size_t k = 0; k < one.history.size(); ++k)
    EXPECT_EQ(one.history[k].qp.iterations, two.history[k].qp.iterations);
  const double difference = (one.u - two.u).norm() / one.u.norm();
  const int64_t a = 3 * problem.equations[0].terms[0].node, b = 3 * problem.equations[0].terms[1].node;
  const int64_t c_y = 3 * problem.equations[0].terms[2].node + 1, a2 = 3 * problem.equations[1].terms[0].node;
  const la::Vector reference = substitution_solve(problem, {{a, {{b, 1.5}, {c_y, -0.25}}}, {a2, {{b, 1.0}}}});
  const double error = (two.u - reference).norm() / reference.norm();
  std::printf("rank %d of 2: |u_2 - u_1|/|u_1| = %.1e, |u_2 - u_ref|/|u_ref| = %.1e, MPRGP steps %d\n", world.rank(),
              difference, error, two.history.back().qp.iterations);
  EXPECT_LT(difference, 1e-12);
  EXPECT_LT(error, 1e-8);
}
