/// 3D Hertz, a sphere on a half-space (issue 20), against Hertz's point contact (Johnson 1985,
/// Contact Mechanics, section 4.2): a = (3 F R / (4 E*))^(1/3), p0 = 3 F / (2 pi a^2),
/// p(r) = p0 sqrt(1 - r^2/a^2). The reference numbers for the default data (E = 2e11 Pa,
/// nu = 0.3, F = 20 kN, R = 50 mm) were evaluated separately with Python from these formulas.
/// Tolerances are the acceptance: peak pressure and contact radius within 2 %, RMS
/// error at most 2 % of p0, contact force equal to the load to 1e-6 (SMALBE-M).

#include "fem/load_history.hpp"
#include "fem/loads.hpp"
#include "mesh/mesh_quality.hpp"
#include "nonlinear/contact_pressure.hpp"
#include "nonlinear/feti_contact_solver.hpp"
#include "problems/hertz3d.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

using namespace feticon;

TEST(Hertz3d, AnalyticValuesOfTheDefaultData)
{
  const problems::Hertz3dAnalytic h = problems::hertz3d_analytic({});
  EXPECT_NEAR(h.contact_radius, 0.0018968553707799233, 1e-15);
  EXPECT_NEAR(h.peak_pressure, 2654012383.2090936, 1e-3);
  EXPECT_NEAR(h.approach, 7.19612059531328e-05, 1e-17);
}

TEST(Hertz3d, ModelGeometryLoadAndMeshQuality)
{
  const problems::Hertz3dParameters parameters;
  const fem::Problem problem = problems::hertz3d_problem(parameters);
  // The load's resultant is F / 4 downward.
  const la::Vector f = problem.external_force();
  Eigen::Vector3d total = Eigen::Vector3d::Zero();
  for (int32_t n = 0; n < problem.mesh.n_nodes(); ++n)
    total += f.segment<3>(3 * n);
  EXPECT_NEAR(total(0), 0, 1e-9);
  EXPECT_NEAR(total(1), 0, 1e-9);
  EXPECT_NEAR(total(2), -0.25 * parameters.load, 1e-9 * parameters.load);
  // The slave face lies on the sphere, the master face on z = 0.
  const double R = parameters.radius;
  for (int32_t n : problem.mesh.face_set_nodes("sphere_contact"))
  {
    const Eigen::Vector3d x = problem.mesh.nodes.row(n).transpose();
    EXPECT_NEAR((x - Eigen::Vector3d(0, 0, R)).norm(), R, 1e-15);
  }
  for (int32_t n : problem.mesh.face_set_nodes("block_contact"))
    EXPECT_EQ(problem.mesh.nodes(n, 2), 0.0);
  const mesh::MeshQuality q = mesh::mesh_quality(problem.mesh, false);
  EXPECT_LE(q.max_aspect_ratio, 3.0);
  EXPECT_GE(q.min_angle_deg, 45.0);
}

TEST(Hertz3d, HalfModelOfATangentialLoadCarriesItWithoutMoment)
{
  // hertz3d.tangential_load: the octant balls mirrored across x = 0 (half model y >= 0), F / 2
  // in the first stage, then Q / 2 along x added with the couple that cancels its moment
  // about the contact point (Cattaneo and Mindlin's load acts in the contact plane). References:
  // the loads' definitions (resultants), statics (moment about the origin), the count the
  // memory guard predicts.
  problems::Hertz3dParameters parameters;
  parameters.tangential_load = 3600;
  const fem::Problem problem = problems::hertz3d_problem(parameters);
  EXPECT_EQ(problem.mesh.n_nodes(), problems::hertz3d_node_count(parameters));
  EXPECT_EQ(problem.mesh.face_sets.count("symmetry_x"), 0u);
  double x_min = 0;
  for (int32_t n : problem.mesh.face_set_nodes("sphere_contact"))
    x_min = std::min(x_min, problem.mesh.nodes(n, 0));
  EXPECT_LT(x_min, -0.001); // both halves of the contact zone
  const fem::LoadHistory history(problem, {.default_steps = 1, .one_step_per_stage = true});
  ASSERT_EQ(history.n_steps(), 2);
  for (int step : {1, 2})
  {
    const la::Vector f = history.external_force(step);
    Eigen::Vector3d total = Eigen::Vector3d::Zero();
    double moment_y = 0; // about the contact point, the origin
    for (int32_t n = 0; n < problem.mesh.n_nodes(); ++n)
    {
      total += f.segment<3>(3 * n);
      moment_y += problem.mesh.nodes(n, 2) * f(3 * n) - problem.mesh.nodes(n, 0) * f(3 * n + 2);
    }
    const double Q = step == 2 ? 0.5 * parameters.tangential_load : 0.0;
    EXPECT_NEAR(total(0), Q, 1e-9 * parameters.load);
    EXPECT_NEAR(total(1), 0, 1e-9 * parameters.load);
    EXPECT_NEAR(total(2), -0.5 * parameters.load, 1e-9 * parameters.load);
    EXPECT_NEAR(moment_y, 0, 1e-12 * parameters.load);
  }
}

namespace
{
struct Hertz3dRun
{
  problems::Hertz3dComparison hertz;
  double force = 0;
  int outer_max = 0;
  int64_t dofs = 0;
};

Hertz3dRun solve(const problems::Hertz3dParameters& parameters, fem::Kinematics kinematics,
                 contact::ContactFormulation formulation = contact::ContactFormulation::mortar)
{
  const fem::Problem problem = problems::hertz3d_problem(parameters);
  nonlinear::SolverSettings s;
  s.kinematics = kinematics;
  s.formulation = formulation;
  s.load_steps = kinematics == fem::Kinematics::linear ? 1 : 2;
  s.dual.preconditioner = dual::DualPreconditioner::dirichlet;
  TimerTable timers;
  const auto solution = nonlinear::solve_feti_contact(problem, s, timers);
  EXPECT_TRUE(solution.converged) << solution.reason;
  const bool large = kinematics == fem::Kinematics::total_lagrangian;
  std::vector<problems::ProfilePoint> radial;
  for (const auto& p : nonlinear::slave_pressure_by_x(problem, solution, kinematics))
    radial.push_back({large ? std::hypot(p.deformed_x, p.deformed_y) : std::hypot(p.x, p.y), p.pressure});
  Hertz3dRun out;
  out.hertz = problems::compare_with_hertz3d(parameters, radial);
  out.force = nonlinear::total_normal_force(solution);
  out.dofs = 3 * static_cast<int64_t>(problem.mesh.n_nodes());
  for (const auto& step : solution.steps)
    out.outer_max = std::max(out.outer_max, step.outer_iterations);
  return out;
}

/// The acceptance of issue 20 for small displacements: peak and contact radius within 2 % of
/// Hertz's, RMS of the pressure within 2 % of p0 over more than 20 nodes, the contact force
/// the load F/4 to 1e-6.
void expect_small_displacement_acceptance(const Hertz3dRun& r, const char* mesh)
{
  const auto& h = r.hertz;
  std::printf("%s: p_peak %.1f MPa (p0 %.1f, %+.2f%%), a %.4f mm (%.4f, %+.2f%%), RMS %.2f%% of p0 over %d nodes, "
              "force / (F/4) - 1 = %.1e\n",
              mesh, h.p_peak_computed / 1e6, h.p0_analytic / 1e6, 100 * (h.p_peak_computed / h.p0_analytic - 1),
              1e3 * h.a_computed, 1e3 * h.a_analytic, 100 * (h.a_computed / h.a_analytic - 1),
              100 * h.rms_error_over_p0, h.nodes_in_rms, r.force / 5000 - 1);
  EXPECT_LT(std::abs(h.p_peak_computed / h.p0_analytic - 1), 0.02) << mesh;
  EXPECT_LT(std::abs(h.a_computed / h.a_analytic - 1), 0.02) << mesh;
  EXPECT_LE(h.rms_error_over_p0, 0.02) << mesh;
  EXPECT_GT(h.nodes_in_rms, 20) << mesh;
  EXPECT_NEAR(r.force, 5000, 1e-6 * 5000) << mesh;
}
} // namespace

TEST(Hertz3d, SmallDisplacementsAgainstHertz)
{
  expect_small_displacement_acceptance(solve({}, fem::Kinematics::linear), "hex8");
}

TEST(Hertz3d, LargeDisplacementsConvergeWithinFifteenOuterIterations)
{
  // The answer moves by about 2 % of p0 from the small-displacement one (docs/contact.md);
  // the bounds are the small-displacement acceptance widened by that, with the limit
  // on the outer iterations.
  const Hertz3dRun r = solve({}, fem::Kinematics::total_lagrangian);
  const auto& h = r.hertz;
  std::printf("large: p_peak %+.2f%%, a %+.2f%%, RMS %.2f%% of p0, outer iterations per step <= %d\n",
              100 * (h.p_peak_computed / h.p0_analytic - 1), 100 * (h.a_computed / h.a_analytic - 1),
              100 * h.rms_error_over_p0, r.outer_max);
  EXPECT_LE(r.outer_max, 15);
  EXPECT_LT(std::abs(h.p_peak_computed / h.p0_analytic - 1), 0.03);
  EXPECT_LT(std::abs(h.a_computed / h.a_analytic - 1), 0.02);
  EXPECT_LE(h.rms_error_over_p0, 0.02);
  // The normal forces act along the deformed normals, inclined by at most about a / R from
  // the vertical dead load, so F/4 <= sum F_n <= F/4 / cos(a/R) (measured: +7e-5).
  EXPECT_GE(r.force, 5000 * (1 - 1e-6));
  EXPECT_LE(r.force, 5000 / std::cos(1.1 * h.a_analytic / 0.05));
}

/// contact.first_rows (FetiContactSolve::rows_reached_from_rest): from rest, the rows near the
/// first touch (0.05 master diagonals) held 35 of the 56 nodes in contact here, and the first
/// QP put the whole load on them. With the rows a rough QP reaches, the first QP has nearly the
/// whole contact zone and the second outer iteration corrects ten times less (measured: 54
/// against 35 nodes, |du|/|u| 6.4e-3 against 6.4e-2). The answer is the same up to the outer
/// tolerance (reference: the run with the near rows): the force residual may be 1e-6 of the
/// 5 kN load, 5 mN, against about 130 N on the peak node (its pressure times its area of about
/// 1/56 of the contact area), so the peak pressures may differ by a few 1e-5 (measured 1.4e-5;
/// 1e-7 with the command line's settings).
TEST(Hertz3d, FirstQpFromRestTakesTheRowsARoughQpReaches)
{
  const fem::Problem problem = problems::hertz3d_problem({});
  nonlinear::SolverSettings s;
  s.dual.preconditioner = dual::DualPreconditioner::dirichlet;
  TimerTable timers;
  s.first_rows_reached = false;
  const auto near = nonlinear::solve_feti_contact(problem, s, timers);
  s.first_rows_reached = true;
  const auto reached = nonlinear::solve_feti_contact(problem, s, timers);
  ASSERT_TRUE(near.converged && reached.converged) << near.reason << reached.reason;
  ASSERT_GE(near.history.size(), 2u);
  ASSERT_GE(reached.history.size(), 2u);
  const double in_contact = static_cast<double>(reached.history.back().active_contacts);
  std::printf("nodes in contact after the first QP: near %lld, reached %lld of %.0f; |du|/|u| of the second: "
              "%.2e, %.2e\n",
              static_cast<long long>(near.history[0].active_contacts),
              static_cast<long long>(reached.history[0].active_contacts), in_contact,
              near.history[1].displacement_change, reached.history[1].displacement_change);
  EXPECT_LT(near.history[0].active_contacts, 0.75 * in_contact);
  EXPECT_GT(reached.history[0].active_contacts, 0.9 * in_contact);
  EXPECT_LT(reached.history[1].displacement_change, 0.2 * near.history[1].displacement_change);
  double peak_near = 0, peak_reached = 0;
  for (const auto& p : nonlinear::slave_pressure_by_x(problem, near, s.kinematics))
    peak_near = std::max(peak_near, p.pressure);
  for (const auto& p : nonlinear::slave_pressure_by_x(problem, reached, s.kinematics))
    peak_reached = std::max(peak_reached, p.pressure);
  EXPECT_NEAR(peak_reached / peak_near, 1.0, 1e-4);
  EXPECT_NEAR(nonlinear::total_normal_force(reached), nonlinear::total_normal_force(near), 1e-6 * 5000);
}

TEST(Hertz3d, DissimilarBlockAgainstHertzWithTheContactModulusOfBoth)
{
  // A steel sphere on an aluminium block (E = 70 GPa, nu = 0.33): frictionless Hertz theory
  // holds with 1/E* = (1 - nu_1^2)/E_1 + (1 - nu_2^2)/E_2 (Johnson 1985, eq. 4.22), so the
  // acceptance of the one-material case applies. E* of steel on steel would put p0 53 % higher:
  // a block given the sphere's material, or E* from one body, fails the bounds.
  problems::Hertz3dParameters parameters;
  parameters.block_material = fem::Material{7.0e10, 0.33};
  const problems::Hertz3dAnalytic steel = problems::hertz3d_analytic({});
  const Hertz3dRun r = solve(parameters, fem::Kinematics::linear);
  const auto& h = r.hertz;
  std::printf("aluminium block: p0 %.1f MPa (steel on steel %.1f), p_peak %+.2f%%, a %+.2f%%, RMS %.2f%% of p0\n",
              h.p0_analytic / 1e6, steel.peak_pressure / 1e6, 100 * (h.p_peak_computed / h.p0_analytic - 1),
              100 * (h.a_computed / h.a_analytic - 1), 100 * h.rms_error_over_p0);
  EXPECT_GT(steel.peak_pressure / h.p0_analytic, 1.5);
  EXPECT_LT(std::abs(h.p_peak_computed / h.p0_analytic - 1), 0.02);
  EXPECT_LT(std::abs(h.a_computed / h.a_analytic - 1), 0.02);
  EXPECT_LE(h.rms_error_over_p0, 0.02);
  EXPECT_NEAR(r.force, 5000, 1e-6 * 5000);
}

// hertz3d split into tetrahedra or wedges (triangular contact faces), coarse (refinement 0.5),
// large displacements: the outer loop must converge. Node-to-segment: before triangles accepted
// projections up to 1e-4 outside with ties to the smaller face, a slave node on the common side
// of two triangles crossed it at every outer iteration and the loop stalled at |du|/|u| ~ 1e-5
// for 15 iterations (tet4, tet10 and wedge6 alike). Mortar: with the master face's normal at
// the closest point, which jumps across the triangles' sides, wedge6 and tet10 cycled between
// two row sets at 1e-5 and 1.1e-6 (contact/mortar_constraints.cpp, row_normal). Reference: the
// load (F/4 = 5000 N on the quarter), which the normal forces carry to within the tilt of the
// deformed normals.
TEST(Hertz3d, LargeDisplacementsOnTriangularFacesConverge)
{
  for (const auto formulation : {contact::ContactFormulation::node_to_segment, contact::ContactFormulation::mortar})
    for (const mesh::CellKind cell : {mesh::CellKind::tet4, mesh::CellKind::wedge6})
    {
      problems::Hertz3dParameters parameters;
      parameters.refinement = 0.5;
      parameters.cell = cell;
      const Hertz3dRun r = solve(parameters, fem::Kinematics::total_lagrangian, formulation);
      const std::string name = std::string(mesh::cell_type(cell).name) +
          (formulation == contact::ContactFormulation::mortar ? " mortar" : " node-to-segment");
      EXPECT_LE(r.outer_max, 15) << name;
      EXPECT_GE(r.force, 5000 * (1 - 1e-6)) << name;
      EXPECT_LE(r.force, 5000 / std::cos(1.1 * r.hertz.a_analytic / 0.05)) << name;
    }
}

// hertz3d meshed by Gmsh (hertz3d.mesh = gmsh): the sphere and the block as OpenCASCADE solids,
// tet10 graded from the contact point, mortar rows on the tri6 faces. Reference: Hertz's p0, a
// and pressure profile, the load; the acceptance of SmallDisplacementsAgainstHertz, at fewer
// DOFs than the hex8 run of SmallDisplacementsAgainstHertz (refinement 1: 39 060 DOFs, peak
// -0.77 %, a -0.17 %, RMS 1.51 % of p0). Measured at refinement 1.7 with the size field's
// growth 1.5 (22 494 DOFs; by the CLI): peak -0.37 %, a +0.32 %, RMS 1.35 % of p0. The mesh's
// bodies and sets are checked by the run itself: loads on "sphere_load", supports on
// "block_support" and the symmetry planes, contact between "sphere_contact" and
// "block_contact"; a set missing or mixed up fails the figures.
TEST(Hertz3d, GmshTet10MeshAgainstHertz)
{
  problems::Hertz3dParameters parameters;
  parameters.gmsh_mesh = true;
  parameters.cell = mesh::CellKind::tet10;
  parameters.refinement = 1.7;
  const Hertz3dRun r = solve(parameters, fem::Kinematics::linear);
  EXPECT_LT(r.dofs, 39060) << "more DOFs than the hex8 run";
  expect_small_displacement_acceptance(r, "Gmsh tet10");
}

// hertz3d with quadratic cells and dual mortar rows on their tri6 and quad8 faces (the
// transformed basis of contact/mortar_face_integration.hpp). Reference: Hertz's p0, a and
// pressure profile, the load. hex20 at refinement 0.7 (58 629 DOFs) meets the acceptance of
// SmallDisplacementsAgainstHertz (measured: peak +0.31 %, a +0.45 %, RMS 1.85 % of p0); with
// node-to-segment rows it gave -2.56 %, +7.74 % and 3.33 %. tet10 at refinement 0.5 (42 444
// DOFs): peak and radius within 2 % (measured -0.11 %, +0.98 %; node-to-segment -3.10 %,
// +4.69 %); its RMS, 4.26 % of p0, is not within 2 % (docs/elements.md), so only printed.
TEST(Hertz3d, QuadraticCellsWithMortarAgainstHertz)
{
  for (const auto& [cell, refinement] : {std::pair{mesh::CellKind::hex20, 0.7}, std::pair{mesh::CellKind::tet10, 0.5}})
  {
    problems::Hertz3dParameters parameters;
    parameters.refinement = refinement;
    parameters.cell = cell;
    const Hertz3dRun r = solve(parameters, fem::Kinematics::linear);
    const auto& h = r.hertz;
    const std::string name(mesh::cell_type(cell).name);
    std::printf("%s: p_peak %+.2f%%, a %+.2f%%, RMS %.2f%% of p0, force / (F/4) - 1 = %.1e\n", name.c_str(),
                100 * (h.p_peak_computed / h.p0_analytic - 1), 100 * (h.a_computed / h.a_analytic - 1),
                100 * h.rms_error_over_p0, r.force / 5000 - 1);
    EXPECT_LT(std::abs(h.p_peak_computed / h.p0_analytic - 1), 0.02) << name;
    EXPECT_LT(std::abs(h.a_computed / h.a_analytic - 1), 0.02) << name;
    if (cell == mesh::CellKind::hex20)
    {
      EXPECT_LE(h.rms_error_over_p0, 0.02) << name;
    }
    EXPECT_NEAR(r.force, 5000, 1e-6 * 5000) << name;
  }
}

namespace
{
/// hertz3d's quarter model with Coulomb friction mu = 0.3 and the lumped preconditioner (the
/// CLI's default in 3D) on `subdomains`, as the CLI runs it (2 load steps with large
/// displacements).
nonlinear::SolverSettings coulomb_settings(fem::Kinematics kinematics, int subdomains)
{
  nonlinear::SolverSettings s;
  s.kinematics = kinematics;
  s.load_steps = kinematics == fem::Kinematics::linear ? 1 : 2;
  s.dual.preconditioner = dual::DualPreconditioner::lumped;
  s.subdomains = subdomains;
  s.friction.model = nonlinear::FrictionModel::coulomb;
  s.friction.coefficient = 0.3;
  return s;
}

/// MPGP steps of the run, after checking that no held friction row carries force.
int steps_with_held_rows_free(const nonlinear::ContactSolution& solution)
{
  for (size_t i = 0; i < solution.tangential.held.size(); ++i)
  {
    if (solution.tangential.held[i])
    {
      EXPECT_EQ(solution.tangential_lambda(static_cast<la::Index>(i)), 0.0);
    }
  }
  int steps = 0;
  for (const auto& outer : solution.history)
    steps += outer.qp.iterations;
  return steps;
}

} // namespace

TEST(Hertz3d, CoulombFrictionAcrossSymmetryPlanesConverges)
{
  // The quarter model with Coulomb friction (mu = 0.3): the tangential rows of slave nodes on
  // x = 0 and y = 0 across their plane repeat the symmetry supports' rows up to the mortar
  // weights beside the plane (contact/tangential_rows.hpp). Not held, they made the second QP
  // stall (20 000 MPGP steps without progress, 4 subdomains, lumped preconditioner: the CLI's
  // auto choice); held only where no weight beside the plane exceeded 1e-3 of the largest,
  // 8 subdomains still stalled ((B B')_CC nearly singular, its inverse amplifying by 2.5e6).
  // For elastically similar bodies friction leaves Hertz's pressure unchanged (the normal and
  // tangential problems uncouple for half-spaces of one material; measured: the frictionless
  // figures to 4 digits): the frictionless acceptance applies.
  const fem::Problem problem = problems::hertz3d_problem({});
  for (const int subdomains : {4, 8})
  {
    SCOPED_TRACE(subdomains);
    const nonlinear::SolverSettings s = coulomb_settings(fem::Kinematics::linear, subdomains);
    TimerTable timers;
    const auto solution = nonlinear::solve_feti_contact(problem, s, timers);
    ASSERT_TRUE(solution.converged) << solution.reason;
    const int steps = steps_with_held_rows_free(solution);
    EXPECT_LE(solution.history.size(), 4u); // measured 3 QPs: stick, Coulomb, settled
    EXPECT_LE(steps, 500);                  // measured 169 (4 subdomains) and 292 (8)
    std::vector<problems::ProfilePoint> radial;
    for (const auto& p :
         nonlinear::slave_pressure_by_x(problem, solution, s.kinematics, s.interaction(problem.contacts[0]).friction))
      radial.push_back({std::hypot(p.x, p.y), p.pressure});
    const problems::Hertz3dComparison h = problems::compare_with_hertz3d({}, radial);
    EXPECT_LT(std::abs(h.p_peak_computed / h.p0_analytic - 1), 0.02);
    EXPECT_LT(std::abs(h.a_computed / h.a_analytic - 1), 0.02);
    EXPECT_LE(h.rms_error_over_p0, 0.02);
    EXPECT_NEAR(nonlinear::total_normal_force(solution), 5000, 1e-6 * 5000);
  }
}

TEST(Hertz3d, CoulombFrictionWithLargeDisplacementsConverges)
{
  // The quarter model with Coulomb friction and large displacements (the CLI's defaults: 2
  // load steps, 4 subdomains, lumped preconditioner). In the current configuration a slave
  // node on a symmetry plane averages the normals of the faces on one side of it (|n_y| =
  // 1.5e-3 measured on the half model); with the held rows' former |n_e| < 1e-3 its
  // across-plane row stayed beside the supports' rows, (B B')_CC was singular, the scaling
  // dropped, and the second outer iteration took 3 237 MPGP steps (107 s). Measured now: 281
  // steps in 5 + 5 outer iterations, 13 s.
  TimerTable timers;
  const auto solution = nonlinear::solve_feti_contact(problems::hertz3d_problem({}),
                                                      coulomb_settings(fem::Kinematics::total_lagrangian, 4), timers);
  ASSERT_TRUE(solution.converged) << solution.reason;
  EXPECT_LE(steps_with_held_rows_free(solution), 600); // measured 281
  EXPECT_LE(solution.history.size(), 14u);             // measured 10 outer iterations
}

TEST(Hertz3d, SphereMovedFarEnoughSlidesEverywhere)
{
  // hertz3d.tangential_displacement: the half model pressed by F with its far face held along
  // x, then that face moved 0.1 mm (20 um slides 77 of 100 nodes at refinement 1). Reference:
  // Coulomb's law at full slide (Mindlin's Q >= mu P): every loaded node slides with a
  // friction force of mu times its normal force, and the friction force along x is mu F / 2.
  // The slip directions turn across x by a few 1e-3 rad (the Poisson expansion under the
  // pressure), so the x-component falls short of the magnitudes' sum by about their square
  // (measured 1.2e-5 at refinement 1, as for the dragged 3D blocks of test_friction_blocks).
  problems::Hertz3dParameters parameters;
  parameters.refinement = 0.7;
  parameters.tangential_displacement = 1e-4;
  parameters.friction_coefficient = 0.3;
  const fem::Problem problem = problems::hertz3d_problem(parameters);
  nonlinear::SolverSettings s = coulomb_settings(fem::Kinematics::linear, 4);
  TimerTable timers;
  const auto solution = nonlinear::solve_feti_contact(problem, s, timers);
  ASSERT_TRUE(solution.converged) << solution.reason;
  double normal = 0, magnitude = 0, along_x = 0;
  int loaded = 0, sliding = 0;
  for (const auto& p :
       nonlinear::slave_pressure_by_x(problem, solution, s.kinematics, s.interaction(problem.contacts[0]).friction))
  {
    if (p.force <= 0)
      continue;
    ++loaded;
    sliding += p.slipping ? 1 : 0;
    normal += p.force;
    magnitude += p.friction_force.norm();
    along_x += p.friction_force.x();
    EXPECT_NEAR(p.friction_force.norm(), 0.3 * p.force, 1e-6 * 0.3 * parameters.load);
  }
  const double mu_F = 0.3 * 0.5 * parameters.load;
  std::printf("full slide: %d of %d loaded nodes slide, friction magnitude - mu N %.1e, x-force + mu F/2 %.1e\n",
              sliding, loaded, magnitude / (0.3 * normal) - 1, along_x / mu_F + 1);
  EXPECT_EQ(sliding, loaded);
  EXPECT_GT(loaded, 20);
  EXPECT_NEAR(normal, 0.5 * parameters.load, 1e-6 * parameters.load);
  EXPECT_NEAR(magnitude, mu_F, 1e-6 * mu_F);
  EXPECT_NEAR(along_x, -mu_F, 1e-4 * mu_F);
}
