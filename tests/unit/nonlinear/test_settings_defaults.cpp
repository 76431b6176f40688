/// The settings tables (io/settings.cpp for the solver, each built-in problem's in src/problems/)
/// declare each user-facing default once. The solver options take theirs from them by
/// construction (SolverSettings, DualPenaltyOptions); the built-in problems' structs keep the
/// geometry of Vondrák et al. 2007 for the tests that build them directly, and this test holds
/// them to the tables. Reference: the tables themselves.

#include "io/settings.hpp"
#include "nonlinear/solver_settings.hpp"
#include "problems/built_in_problem.hpp"
#include "problems/cantilever_obstacle.hpp"
#include "problems/hertz.hpp"
#include "problems/hertz3d.hpp"

#include <gtest/gtest.h>

namespace feticon
{
namespace
{
const io::Settings table(problems::setting_specs());

TEST(SettingsDefaults, SolverOptionsAreTheTables)
{
  const nonlinear::SolverSettings s;
  // The three that once had a second, different default in the structs.
  EXPECT_EQ(table.text("displacements"), "large");
  EXPECT_EQ(s.kinematics, fem::Kinematics::total_lagrangian);
  EXPECT_TRUE(table.is_auto("load_steps"));
  EXPECT_EQ(s.load_steps, 1); // without friction
  io::Settings coulomb = table;
  coulomb.set("contact.friction.model", "coulomb", "test");
  EXPECT_EQ(nonlinear::SolverSettings(coulomb).load_steps, 2);
  coulomb.set("load_steps", "3", "test");
  EXPECT_EQ(nonlinear::SolverSettings(coulomb).load_steps, 3);
  // A pair's own friction makes auto two steps on its problem (SolverSettings::steps_of).
  fem::Problem with_friction;
  with_friction.contacts.push_back({"s", "m"});
  EXPECT_EQ(s.steps_of(with_friction), 1);
  with_friction.contacts[0].interaction.friction = {fem::FrictionModel::coulomb, 0.3, 0};
  EXPECT_EQ(s.steps_of(with_friction), 2);
  // auto is resolved by the app (app/feti_choice); the library takes the Dirichlet one and 8.
  EXPECT_EQ(table.text("qp.preconditioner"), "auto");
  EXPECT_EQ(s.dual.preconditioner, dual::DualPreconditioner::dirichlet);
  EXPECT_EQ(s.dual.rho, table.number("rho"));
  EXPECT_EQ(s.dual.rtol, table.number("qp.rtol"));
  EXPECT_EQ(s.dual.max_iterations, table.integer("qp.max_iterations"));
  EXPECT_EQ(s.max_outer_iterations, table.integer("newton.max_iterations"));
  EXPECT_EQ(s.forcing, table.number("newton.forcing"));
  EXPECT_EQ(table.text("contact.first_rows"), "reached");
  EXPECT_TRUE(s.first_rows_reached);
  EXPECT_TRUE(table.is_auto("subdomains"));
  EXPECT_EQ(s.subdomains, 8);
  EXPECT_EQ(s.eps_n_factor, table.number("eps_n"));
  // Small displacements take the load in one step whatever load_steps says.
  nonlinear::SolverSettings small = s;
  small.kinematics = fem::Kinematics::linear;
  EXPECT_EQ(small.steps(), 1);
  EXPECT_EQ(s.steps(), 1);
}

// Each pair carries its interaction (a deck's *FRICTION and pair TYPE, a problem file's pair);
// the settings contact.friction.* and contact.formulation replace it for every pair where
// given, key by key, and leave it where not. Reference: the rule of SolverSettings::interaction.
TEST(SettingsDefaults, GivenContactKeysOverrideEveryPairsInteractionKeyByKey)
{
  fem::ContactPairNames pair{"s", "m"};
  pair.interaction.friction = {fem::FrictionModel::coulomb, 0.3, 0};
  pair.interaction.formulation = fem::ContactFormulation::node_to_segment;
  const fem::ContactInteraction own = nonlinear::SolverSettings(table).interaction(pair);
  EXPECT_EQ(own.friction.model, fem::FrictionModel::coulomb);
  EXPECT_EQ(own.friction.coefficient, 0.3);
  EXPECT_EQ(own.formulation, fem::ContactFormulation::node_to_segment);
  io::Settings coefficient = table;
  coefficient.set("contact.friction.coefficient", "0.5", "--set");
  EXPECT_EQ(nonlinear::SolverSettings(coefficient).interaction(pair).friction.model, fem::FrictionModel::coulomb);
  EXPECT_EQ(nonlinear::SolverSettings(coefficient).interaction(pair).friction.coefficient, 0.5);
  io::Settings none = table;
  none.set("contact.friction.model", "none", "--set");
  EXPECT_EQ(nonlinear::SolverSettings(none).interaction(pair).friction.model, fem::FrictionModel::none);
  io::Settings mortar = table;
  mortar.set("contact.formulation", "mortar", "--set");
  EXPECT_EQ(nonlinear::SolverSettings(mortar).interaction(pair).formulation, fem::ContactFormulation::mortar);
  // A rerun of problem.yaml keeps the pair's own: the keys not given are written commented out.
  const std::string yaml = table.to_yaml();
  EXPECT_NE(yaml.find("# contact.formulation: mortar (not given: each contact pair's own)"), std::string::npos);
  EXPECT_EQ(yaml.find("\ncontact.friction.model:"), std::string::npos);
  EXPECT_NE(mortar.to_yaml().find("\ncontact.formulation: mortar\n"), std::string::npos);
}

// The dual penalty's rho unless given is 1e3, not SMALBE-M's 1: its feasibility error falls
// like 1 / rho, 0.27 at rho = 1 on Hertz (docs/contact.md), and rho = 1e3 is the first decade
// under contact.feasibility_tolerance. Reference: the measured 1 / rho law.
TEST(SettingsDefaults, DualPenaltyTakesItsOwnRhoUnlessGiven)
{
  io::Settings settings = table;
  settings.set("method", "dual_penalty", "test");
  EXPECT_EQ(dual::DualPenaltyOptions(settings).rho, 1e3);
  EXPECT_LT(0.27 / dual::DualPenaltyOptions(settings).rho, table.number("contact.feasibility_tolerance"));
  settings.set("rho", "10", "test");
  EXPECT_EQ(dual::DualPenaltyOptions(settings).rho, 10);
  io::Settings smalbe = table;
  EXPECT_EQ(dual::DualPenaltyOptions(smalbe).rho, 1);
}

TEST(SettingsDefaults, BuiltInProblemsAgreeWithTheTable)
{
  const problems::HertzParameters hertz;
  EXPECT_EQ(hertz.line_load, table.number("hertz.line_load"));
  EXPECT_EQ(hertz.mesh.kind == problems::HertzMeshKind::graded ? "graded" : "tensor", table.text("hertz.mesh"));
  EXPECT_EQ(hertz.mesh.refinement, table.number("hertz.refinement"));
  EXPECT_EQ(hertz.mesh.element_size, table.number("hertz.element_size"));
  EXPECT_EQ(hertz.mesh.master_ratio, table.number("hertz.master_ratio"));
  EXPECT_EQ(hertz.mesh.block_width, table.number("hertz.block_width"));
  EXPECT_EQ(hertz.mesh.block_depth, table.number("hertz.block_depth"));
  EXPECT_EQ(hertz.mesh.cylinder_width, table.number("hertz.cylinder_width"));
  EXPECT_EQ(hertz.mesh.growth_ratio, table.number("hertz.growth_ratio"));
  EXPECT_EQ(hertz.material.young, table.number("material.young"));
  EXPECT_EQ(hertz.material.poisson, table.number("material.poisson"));

  const problems::Hertz3dParameters hertz3d;
  EXPECT_EQ(hertz3d.radius, table.number("hertz3d.radius"));
  EXPECT_EQ(hertz3d.load, table.number("hertz3d.load"));
  EXPECT_EQ(hertz3d.element_size, table.number("hertz3d.element_size"));
  EXPECT_EQ(hertz3d.refinement, table.number("hertz3d.refinement"));
  EXPECT_EQ(hertz3d.master_ratio, table.number("hertz3d.master_ratio"));
  EXPECT_EQ(hertz3d.block_radius, table.number("hertz3d.block_radius"));
  EXPECT_EQ(hertz3d.cap_radius, table.number("hertz3d.cap_radius"));
  EXPECT_EQ(hertz3d.radial_aspect, table.number("hertz3d.radial_aspect"));

  const problems::CantileverObstacleParameters cantilever;
  EXPECT_EQ(cantilever.gap, table.number("cantilever.gap"));
  EXPECT_EQ(cantilever.linear_deflection_ratio, table.number("cantilever.load"));
  EXPECT_EQ(cantilever.cells_along, table.integer("cantilever.cells"));
}
} // namespace
} // namespace feticon
