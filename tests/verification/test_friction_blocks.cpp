/// Tresca and Coulomb friction on two blocks in plane strain (issue 39): an upper block pressed
/// onto a clamped lower one by a pressure p and pulled along the interface by a shear traction
/// q on its top face, or dragged by a prescribed displacement of its top face.
/// References: equilibrium (the upper block is held along x by friction alone, so the friction
/// forces sum to the applied shear force q A), the slip bound (|t_T| <= g at every node, Tresca;
/// <= mu t_N, Coulomb), and a block dragged far enough slides at every node, so the friction
/// force is the bound integrated over the interface: g A (Tresca), mu p A (Coulomb).

#include "contact/tangential_rows.hpp"
#include "common/error.hpp"
#include "mesh/box.hpp"
#include "nonlinear/contact_pressure.hpp"
#include "nonlinear/feti_contact_solver.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <set>

using namespace feticon;

namespace
{
constexpr double pressure = 1e8; // Pa; the interface is 1 x 1 (plane strain: 1 m thick)

/// Lower block [0,1] x [0,1] x [0,1] clamped at z = 0, upper block [0,1] x [0,1] x [1,1.25] on
/// top of it (non-matching: 4 against 5 cells along x), in plane strain one cell thick in y with
/// u_y eliminated (box friction), else 4 against 5 cells along y too (disc friction). Top face: traction
/// (q, 0, -p), or, with `drag` > 0, the pressure and u_x = drag prescribed (and u_y = 0 in 3D
/// where `hold_across`).
fem::Problem sheared_blocks(double q, double drag, bool plane_strain = true, bool hold_across = true)
{
  mesh::BoxParameters lower;
  lower.nx = lower.nz = 4;
  lower.ny = plane_strain ? 1 : 4;
  lower.body_name = "lower";
  mesh::BoxParameters upper = lower;
  upper.nx = 5;
  upper.ny = plane_strain ? 1 : 5;
  upper.nz = 2;
  upper.lengths = Eigen::Vector3d(1, 1, 0.25); // flat: the friction's moment tilts it little
  upper.origin = Eigen::Vector3d(0, 0, 1);
  upper.body_name = "upper";
  fem::Problem p;
  p.name = "sheared blocks";
  p.mesh = mesh::generate_box(lower);
  mesh::append_mesh(p.mesh, mesh::generate_box(upper), "upper_");
  p.materials.assign(2, fem::Material{2e11, 0.3});
  p.eliminated = {false, plane_strain, false};
  p.steps.front().dirichlet = {{"zmin", {0.0, plane_strain ? std::nullopt : std::optional<double>(0.0), 0.0}}};
  if (drag > 0)
    p.steps.front().dirichlet.push_back(
        {"upper_zmax", {drag, plane_strain || !hold_across ? std::nullopt : std::optional<double>(0.0), std::nullopt}});
  p.steps.front().tractions = {{"upper_zmax", Eigen::Vector3d(drag > 0 ? 0.0 : q, 0, -pressure)}};
  p.contacts = {{"upper_zmin", "zmax"}};
  p.validate();
  return p;
}

nonlinear::SolverSettings settings(nonlinear::FrictionModel model, double bound)
{
  nonlinear::SolverSettings s;
  s.kinematics = fem::Kinematics::linear;
  s.dual.rtol = 1e-10;
  s.subdomains = 4;
  s.formulation = contact::ContactFormulation::mortar;
  s.friction.model = model;
  if (model == nonlinear::FrictionModel::tresca)
    s.friction.slip_bound = bound;
  else
    s.friction.coefficient = bound;
  return s;
}

struct FrictionFigures
{
  double force_x = 0;     ///< friction force on the upper block along x (N)
  double force_y = 0;     ///< and along y
  double magnitudes = 0;  ///< sum over the slave nodes of |t_T| (N)
  double worst_ratio = 0; ///< max over slave nodes of |t_T| / bound
  int sliding = 0, nodes = 0;
};

/// Friction forces on the slave (upper) block and their ratio to the bound, per slave node:
/// g D_j (Tresca) or mu times the node's normal force (Coulomb).
FrictionFigures friction_figures(const fem::Problem& p, const nonlinear::ContactSolution& s,
                                 const nonlinear::Friction& friction)
{
  const la::Vector f = contact::tangential_forces(s.tangential, s.tangential_lambda, 3 * p.mesh.n_nodes());
  std::map<int32_t, double> normal_force, area;
  for (size_t i = 0; i < s.constraints.slave_node.size(); ++i)
  {
    normal_force[s.constraints.slave_node[i]] = s.contact_lambda(i) / s.constraints.row_norm[i];
    area[s.constraints.slave_node[i]] = s.constraints.slave_area[i];
  }
  FrictionFigures out;
  for (const int32_t node : std::set<int32_t>(s.tangential.slave_node.begin(), s.tangential.slave_node.end()))
  {
    const double t = std::hypot(f(3 * node), f(3 * node + 1));
    const double bound = friction.model == nonlinear::FrictionModel::tresca ? friction.slip_bound * area[node]
                                                                            : friction.coefficient * normal_force[node];
    out.force_x += f(3 * node);
    out.force_y += f(3 * node + 1);
    out.magnitudes += t;
    ++out.nodes;
    if (bound > 0)
    {
      out.worst_ratio = std::max(out.worst_ratio, t / bound);
      out.sliding += t >= (1 - 1e-5) * bound; // Coulomb's bound settles to the tolerance 1e-6
    }
  }
  return out;
}
} // namespace

// Tresca, g = 0.4 p: a shear q = 0.3 p is held (friction force -q A, the bound kept), a block
// dragged 10 mm slides at every node and the friction force is -g A.
TEST(FrictionBlocks, TrescaHoldsTheShearBelowTheBoundAndSlidesAtIt)
{
  const double g = 0.4 * pressure;
  const auto s = settings(nonlinear::FrictionModel::tresca, g);
  {
    const fem::Problem problem = sheared_blocks(0.3 * pressure, 0);
    TimerTable timers;
    const auto solution = nonlinear::solve_feti_contact(problem, s, timers);
    ASSERT_TRUE(solution.converged) << solution.reason;
    const FrictionFigures r = friction_figures(problem, solution, s.interaction(problem.contacts[0]).friction);
    std::printf("Tresca stick: friction force %.9e (applied %.9e), max |t|/g %.6f, %d of %d nodes at g\n", r.force_x,
                -0.3 * pressure, r.worst_ratio, r.sliding, r.nodes);
    EXPECT_NEAR(r.force_x, -0.3 * pressure, 1e-6 * 0.3 * pressure);
    EXPECT_LE(r.worst_ratio, 1 + 1e-8);
    EXPECT_LT(r.sliding, r.nodes) << "a shear below the bound should leave nodes sticking";
    EXPECT_NEAR(nonlinear::total_normal_force(solution), pressure, 1e-6 * pressure);
  }
  {
    const fem::Problem problem = sheared_blocks(0, 1e-2);
    TimerTable timers;
    const auto solution = nonlinear::solve_feti_contact(problem, s, timers);
    ASSERT_TRUE(solution.converged) << solution.reason;
    const FrictionFigures r = friction_figures(problem, solution, s.interaction(problem.contacts[0]).friction);
    std::printf("Tresca slide: friction force %.9e (g A %.9e), %d of %d nodes at g\n", r.force_x, -g, r.sliding,
                r.nodes);
    EXPECT_EQ(r.sliding, r.nodes);
    EXPECT_NEAR(r.force_x, -g, 1e-6 * g);
  }
}

// Coulomb, mu = 0.3: a shear 0.2 p is held; dragged, the block slides everywhere with the
// friction force mu times the normal force p A (the fixed point on the bound settled).
TEST(FrictionBlocks, CoulombHoldsTheShearBelowMuPAndSlidesAtIt)
{
  const double mu = 0.3;
  const auto s = settings(nonlinear::FrictionModel::coulomb, mu);
  {
    const fem::Problem problem = sheared_blocks(0.2 * pressure, 0);
    TimerTable timers;
    const auto solution = nonlinear::solve_feti_contact(problem, s, timers);
    ASSERT_TRUE(solution.converged) << solution.reason;
    const FrictionFigures r = friction_figures(problem, solution, s.interaction(problem.contacts[0]).friction);
    std::printf("Coulomb stick: friction force %.9e (applied %.9e), max |t|/(mu t_N) %.6f, %d of %d nodes at the "
                "bound, %zu QPs\n",
                r.force_x, -0.2 * pressure, r.worst_ratio, r.sliding, r.nodes, solution.history.size());
    EXPECT_NEAR(r.force_x, -0.2 * pressure, 1e-6 * 0.2 * pressure);
    EXPECT_LE(r.worst_ratio, 1 + 1e-5);
  }
  {
    const fem::Problem problem = sheared_blocks(0, 1e-2);
    TimerTable timers;
    const auto solution = nonlinear::solve_feti_contact(problem, s, timers);
    ASSERT_TRUE(solution.converged) << solution.reason;
    const FrictionFigures r = friction_figures(problem, solution, s.interaction(problem.contacts[0]).friction);
    const double normal = nonlinear::total_normal_force(solution);
    std::printf("Coulomb slide: friction force %.9e (mu N %.9e), %d of %d nodes at the bound, %zu QPs\n", r.force_x,
                -mu * normal, r.sliding, r.nodes, solution.history.size());
    EXPECT_EQ(r.sliding, r.nodes);
    EXPECT_NEAR(r.force_x, -mu * normal, 1e-6 * mu * normal);
  }
}

// 3D: the tangential multipliers of a node in the disc of its bound (MPGP inside SMALBE-M).
// Tresca g = 0.4 p holds a shear 0.3 p along x and, dragged 10 mm along x, slides at every
// node with the friction force -g A along x and none along y; Coulomb mu = 0.3 likewise with
// the bound mu t_N.
TEST(FrictionBlocks, DiscsHoldAndSlideIn3D)
{
  for (const auto model : {nonlinear::FrictionModel::tresca, nonlinear::FrictionModel::coulomb})
  {
    const bool tresca = model == nonlinear::FrictionModel::tresca;
    const auto s = settings(model, tresca ? 0.4 * pressure : 0.3);
    {
      const fem::Problem problem = sheared_blocks(0.2 * pressure, 0, false);
      TimerTable timers;
      const auto solution = nonlinear::solve_feti_contact(problem, s, timers);
      ASSERT_TRUE(solution.converged) << solution.reason;
      const FrictionFigures r = friction_figures(problem, solution, s.interaction(problem.contacts[0]).friction);
      std::printf("3D %s stick: friction force (%.9e, %.2e) (applied %.9e), max |t|/bound %.6f, %d of %d nodes at "
                  "the bound, %zu QPs\n",
                  tresca ? "Tresca" : "Coulomb", r.force_x, r.force_y, -0.2 * pressure, r.worst_ratio, r.sliding,
                  r.nodes, solution.history.size());
      EXPECT_NEAR(r.force_x, -0.2 * pressure, 1e-6 * 0.2 * pressure);
      EXPECT_NEAR(r.force_y, 0, 1e-6 * 0.2 * pressure);
      EXPECT_LE(r.worst_ratio, 1 + 1e-5);
      EXPECT_LT(r.sliding, r.nodes);
    }
    {
      const fem::Problem problem = sheared_blocks(0, 1e-2, false);
      TimerTable timers;
      const auto solution = nonlinear::solve_feti_contact(problem, s, timers);
      ASSERT_TRUE(solution.converged) << solution.reason;
      const FrictionFigures r = friction_figures(problem, solution, s.interaction(problem.contacts[0]).friction);
      const double expected = tresca ? 0.4 * pressure : 0.3 * nonlinear::total_normal_force(solution);
      std::printf("3D %s slide: sum |t_T| %.9e, friction force (%.9e, %.2e) (bound %.9e), %d of %d nodes at the "
                  "bound, %zu QPs\n",
                  tresca ? "Tresca" : "Coulomb", r.magnitudes, r.force_x, r.force_y, -expected, r.sliding, r.nodes,
                  solution.history.size());
      EXPECT_EQ(r.sliding, r.nodes);
      EXPECT_NEAR(r.magnitudes, expected, 1e-6 * expected);
      // The slip is along x up to the Poisson expansion of the pressed blocks across it (about
      // nu p / E = 1.5e-4 of their width against the 10 mm drag): x carries all but 1e-4.
      EXPECT_NEAR(r.force_x, -expected, 1e-4 * expected);
      EXPECT_NEAR(r.force_y, 0, 1e-6 * expected);
    }
  }
}

// The blocks tilted by alpha about y (the interface an inclined plane), the upper one pressed by
// a vertical traction p (its weight): along the plane the load is p sin(alpha) A, across it
// p cos(alpha) A. Reference: Coulomb's law; mu = 0.3 > tan(10 deg) = 0.18 holds the block
// with the friction force p sin(alpha) A; mu < tan(20 deg) = 0.36 cannot, and the run says the
// block slides.
TEST(FrictionBlocks, BlockOnAnInclinedPlaneSticksOrSlidesByMuAgainstTanAlpha)
{
  const double mu = 0.3;
  for (const double degrees : {10.0, 20.0})
  {
    const double alpha = degrees * M_PI / 180;
    fem::Problem problem = sheared_blocks(0, 0);
    const Eigen::Matrix3d R = Eigen::AngleAxisd(alpha, Eigen::Vector3d::UnitY()).toRotationMatrix();
    for (la::Index n = 0; n < problem.mesh.nodes.rows(); ++n)
      problem.mesh.nodes.row(n) = (R * problem.mesh.nodes.row(n).transpose()).transpose();
    problem.steps.front().tractions = {{"upper_zmax", Eigen::Vector3d(0, 0, -pressure)}};
    const auto s = settings(nonlinear::FrictionModel::coulomb, mu);
    TimerTable timers;
    if (std::tan(alpha) < mu)
    {
      const auto solution = nonlinear::solve_feti_contact(problem, s, timers);
      ASSERT_TRUE(solution.converged) << solution.reason;
      const la::Vector f =
          contact::tangential_forces(solution.tangential, solution.tangential_lambda, 3 * problem.mesh.n_nodes());
      Eigen::Vector3d total = Eigen::Vector3d::Zero();
      for (const int32_t node :
           std::set<int32_t>(solution.tangential.slave_node.begin(), solution.tangential.slave_node.end()))
        total += f.segment<3>(3 * node);
      const double along = total.dot(R * Eigen::Vector3d::UnitX()); // down the plane is -x'
      std::printf("inclined %.0f deg: friction force along the plane %.9e (p sin(alpha) A = %.9e), normal %.9e "
                  "(p cos(alpha) A = %.9e)\n",
                  degrees, along, pressure * std::sin(alpha), nonlinear::total_normal_force(solution),
                  pressure * std::cos(alpha));
      // The load pushes the upper block down the plane (-x' for a rotation by +alpha about y
      // lifts +x'): friction holds it up the plane.
      EXPECT_NEAR(std::abs(along), pressure * std::sin(alpha), 1e-6 * pressure);
      EXPECT_NEAR(nonlinear::total_normal_force(solution), pressure * std::cos(alpha), 1e-6 * pressure);
    }
    else
    {
      try
      {
        const auto solution = nonlinear::solve_feti_contact(problem, s, timers);
        ADD_FAILURE() << "mu below tan(alpha): the block should slide, the run converged: " << solution.converged;
      }
      catch (const Error& e)
      {
        std::printf("inclined %.0f deg: %s\n", degrees, e.what());
        EXPECT_NE(std::string(e.what()).find("slides"), std::string::npos) << e.what();
      }
    }
  }
}

// 3D, dragged along x with the top free along y: every node slides, and nothing but the slip
// direction holds the block across it. Primal recovery takes that from the discs at their bound
// (the slip across lambda_T is zero: dual/primal_recovery.hpp); before, the run stopped at
// "every tangential row slides". Reference: Coulomb's and Tresca's law, as with the top held
// in y (DiscsHoldAndSlideIn3D): the friction force's magnitudes sum to the bound, along x;
// across, the block moves by the Poisson expansion's share only.
TEST(FrictionBlocks, BlockDraggedWithItsTopFreeAcrossSlidesAlongTheDrag)
{
  for (const auto model : {nonlinear::FrictionModel::tresca, nonlinear::FrictionModel::coulomb})
  {
    const bool tresca = model == nonlinear::FrictionModel::tresca;
    const auto s = settings(model, tresca ? 0.4 * pressure : 0.3);
    const fem::Problem problem = sheared_blocks(0, 1e-2, false, false);
    TimerTable timers;
    const auto solution = nonlinear::solve_feti_contact(problem, s, timers);
    ASSERT_TRUE(solution.converged) << solution.reason;
    const FrictionFigures r = friction_figures(problem, solution, s.interaction(problem.contacts[0]).friction);
    const double expected = tresca ? 0.4 * pressure : 0.3 * nonlinear::total_normal_force(solution);
    double shift = 0, spread = 0; // mean and largest |u_y| of the upper block's top face
    const std::vector<int32_t>& top = problem.mesh.node_set("upper_zmax");
    for (const int32_t node : top)
    {
      shift += solution.u(3 * node + 1) / static_cast<double>(top.size());
      spread = std::max(spread, std::abs(solution.u(3 * node + 1)));
    }
    std::printf("3D %s slide, top free across: sum |t_T| %.9e (bound %.9e), friction force (%.9e, %.2e), %d of %d "
                "nodes at the bound; the top's u_y: mean %.2e m, largest %.2e m against the 1e-2 m drag\n",
                tresca ? "Tresca" : "Coulomb", r.magnitudes, expected, r.force_x, r.force_y, r.sliding, r.nodes, shift,
                spread);
    EXPECT_EQ(r.sliding, r.nodes);
    EXPECT_NEAR(r.magnitudes, expected, 1e-6 * expected);
    EXPECT_NEAR(r.force_x, -expected, 1e-4 * expected);
    EXPECT_NEAR(r.force_y, 0, 1e-6 * expected);
    // The problem is symmetric about y = 0.5: the block does not drift across the drag (its
    // top's mean u_y at most 1e-4 of the drag), and its top spreads by the Poisson expansion's
    // order (nu p / E = 1.5e-4 of its 1 m width).
    EXPECT_LT(std::abs(shift), 1e-6);
    EXPECT_LT(spread, 1.5e-4);
  }
}
