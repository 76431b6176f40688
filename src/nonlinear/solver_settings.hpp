#pragma once
/// @file Settings of the contact solvers (plain struct with documented defaults).

#include "contact/contact_constraints.hpp"
#include "decomposition/generalized_inverse.hpp"
#include "dual/dual_penalty_problem.hpp"
#include "fem/load_history.hpp"
#include "fem/material.hpp"
#include "fem/problem.hpp"
#include "io/settings.hpp"

#include <optional>
#include <string>

namespace feticon::nonlinear
{
enum class ContactMethod
{
  smalbe,        ///< FETI, SMALBE-M + MPRGP (G lambda = e exact)
  dual_penalty,  ///< FETI, MPRGP on problem (9) of Vondrák et al. 2007
  primal_penalty ///< undecomposed, penalty springs eps_n <g>, CHOLMOD
};

/// Which stiffness the FETI outer loop uses (ALGORITHMS.md section 8). Never the full
/// tangent K_T: for a stressed floating subdomain its kernel is not the rigid modes.
enum class StiffnessUpdate
{
  initial,   ///< K_0 assembled and factorized once (the modified Newton–Raphson of Vondrák et al. 2007)
  load_step, ///< K_M(u) with R from x = X + u, refreshed at the start of every load step
  iteration  ///< K_M(u) refreshed at every outer iteration
};

/// How the cells are split into subdomains (decomposition/partition.hpp).
enum class Partitioner
{
  metis,     ///< METIS k-way on the cell face graph
  rcb,       ///< recursive coordinate bisection: box-like subdomains
  structured ///< equal slabs along x per body (studies)
};

/// How F and the Dirichlet preconditioner are applied (decomposition/explicit_boundary_operators.hpp).
enum class DualOperatorMode
{
  implicit,  ///< substitutions with the subdomain factors at every application
  explicit_, ///< dense blocks on the subdomain boundaries, formed once per factorization
  automatic  ///< explicit where the blocks fit the memory budget and pay for their set-up
};

/// The settings of a contact solve. The values a user sets come from the settings table
/// (io/settings.cpp), where each default is declared once: a default-built SolverSettings
/// holds those defaults; the fields without a setting have theirs here.
using FrictionModel = fem::FrictionModel;
using Friction = fem::Friction;

/// The settings contact.friction.* that were given (a problem file's settings or --set): each
/// replaces that field of every pair's friction; an empty one leaves the pair's own.
struct FrictionOverride
{
  std::optional<FrictionModel> model;
  std::optional<double> coefficient;
  std::optional<double> slip_bound;
};

struct SolverSettings
{
  SolverSettings();
  /// From the settings `method`, `displacements`, `load_steps`, `newton.*`, `subdomains`,
  /// `partitioner`, `dual.operator`, `contact.formulation`, `eps_n` and the dual's (rho,
  /// smalbe.*, qp.*). `subdomain_cells` needs the mesh: app::solver_settings applies it, and
  /// resolves `subdomains = auto` and `qp.preconditioner = auto` from the model's size and the
  /// machine's memory (app/feti_choice.hpp). Made here from settings at auto, they are the
  /// fixed values of before issue 40, 8 subdomains and the Dirichlet preconditioner (the
  /// library's callers, the tests among them, get reproducible runs).
  explicit SolverSettings(const io::Settings& settings);

  /// Load steps of the first load stage (all of a one-stage problem): load_steps with large
  /// displacements, one with small ones (linear elasticity takes the whole load in one step;
  /// contact's own nonlinearity is the outer loop's).
  int steps() const { return kinematics == fem::Kinematics::linear ? 1 : load_steps; }
  /// Whether `problem`'s answer at a step's end is independent of the load path, so that each
  /// step takes one load step: small displacements and no plastic body (friction's path is
  /// its load steps' own business, LoadHistory).
  bool path_independent(const fem::Problem& problem) const
  {
    return kinematics == fem::Kinematics::linear && !problem.has_plastic_body() && !has_nonlinear_law(problem);
  }
  /// Whether a pair of `problem` is solved with an exponential or tabular law in some step: its
  /// outer loop follows the law's tangent (fem::NormalLaw::tangent), also with small displacements.
  bool has_nonlinear_law(const fem::Problem& problem) const;
  /// The same for `problem`: load_steps = auto is two where a pair has friction or a body is
  /// plastic (both follow the path in its steps), else one.
  int steps_of(const fem::Problem& problem) const
  {
    if (path_independent(problem))
      return 1;
    return auto_load_steps && (has_friction(problem) || problem.has_plastic_body()) ? 2 : load_steps;
  }
  /// The load history of `problem` under these settings: steps_of(problem) load steps where a
  /// step does not give its increments; with small displacements and elastic bodies each step
  /// without amplitudes in one load step (frictionless contact of linear elastic bodies: the
  /// answer at a step's end does not depend on the path, so one QP per step gives CalculiX's
  /// per-step results), a step with amplitudes or friction in its increments (where it gives none,
  /// load_steps, auto: one).
  /// A step's automatic increments (a deck's *STATIC) are its own, but an explicit load_steps
  /// runs step 1 in load_steps equal ones.
  fem::LoadHistory load_history(const fem::Problem& problem) const
  {
    const bool linear = path_independent(problem);
    const bool friction = has_friction(problem);
    return fem::LoadHistory(problem,
                            {.default_steps = !linear ? steps_of(problem)
                                 : auto_load_steps    ? 1
                                                      : load_steps,
                             .one_step_per_stage = linear && !friction,
                             .default_first = !auto_load_steps,
                             .grow = !friction || tied_friction_slaves(problem) == 0});
  }
  /// Load steps of the whole run on `problem` (load_history(problem).n_steps()).
  int steps(const fem::Problem& problem) const { return load_history(problem).n_steps(); }

  ContactMethod method;
  fem::Kinematics kinematics;
  int load_steps; ///< equal load increments (large displacements; auto resolved)
  /// load_steps was auto: 1, or 2 on a problem with friction (steps_of).
  bool auto_load_steps = false;
  int max_outer_iterations; ///< outer (Newton) iterations per load step
  /// Cutbacks of a load step in a row (nonlinear/load_stepping.hpp): one increment of the
  /// whole load, halved where it fails, took 13-47 % fewer MPRGP steps than two on Hertz and
  /// hertz3d (docs/contact.md, "One load increment, cut back where it fails").
  int max_cutbacks;
  /// eps_u and eps_r of OuterConvergence (eps_r: FETI solver). 1e-4 saved 3-21 % of the
  /// MPRGP steps but left the multiplier of the Hertz axis node 1.6 % off with rho = 10 (the
  /// peak pressure +0.64 % instead of -0.73 %; docs/contact.md): 1e-6 keeps it to 1e-7.
  double displacement_tolerance;
  double residual_tolerance;
  StiffnessUpdate stiffness;
  /// newton.stiffness was auto: `stiffness` is initial, stiffness_of(problem) decides.
  bool stiffness_auto = false;
  /// The stiffness update on `problem`: `stiffness`, or for newton.stiffness = auto the
  /// consistent tangent at every outer iteration where a body is plastic (on the Hertz J2
  /// half-space 5 outer iterations and 4.0 s against K_0's 18, not converged, in 6.3 s:
  /// docs/materials.md) or where large displacements turn a kinematic coupling by finite
  /// rotations (a bar's rigid end turned 30 degrees in ten increments: 4-5 outer iterations each
  /// against K_0's 12-15, which stalled at a twelfth of the way: docs/contact.md, "Couplings"),
  /// K_0 otherwise.
  StiffnessUpdate stiffness_of(const fem::Problem& problem) const
  {
    const bool turned = kinematics != fem::Kinematics::linear && problem.has_finite_couplings();
    return stiffness_auto && (problem.has_inelastic_or_hyperelastic_body() || turned) ? StiffnessUpdate::iteration
                                                                                      : stiffness;
  }
  /// Inexact outer iterations (large displacements): the QP of outer iteration k > 1 stops at
  /// rtol = max(dual.rtol, min(max_forcing_rtol, forcing * ||du_{k-1}|| / ||u||)), the
  /// first of a step at max_forcing_rtol. An outer iteration re-linearizes around the
  /// current u and solves for the total multipliers, so a QP error does not accumulate: the
  /// next iteration's residual corrects it, and QP accuracy beyond the size of the next
  /// correction is work thrown away. 0 solves every QP to dual.rtol. The QP error reaches
  /// du amplified (by the conditioning of H), so the factor is small: on Hertz at
  /// refinement 0.5 and 1 (two load steps), 0.01 and 0.003 took one or two more outer
  /// iterations per step than exact QPs, 0.3 stalled at |du|/|u| ~ 1e-4; 0.001 takes the
  /// same outer iterations with 57 % and 64 % of the MPRGP steps. On a slender cantilever
  /// with K_M refreshed, 0.01 cycled; so once a correction grows, the rest of the load step
  /// uses exact QPs.
  double forcing;
  double max_forcing_rtol = 1e-4;
  int subdomains;
  Partitioner partitioner;
  DualOperatorMode dual_operator;
  /// qp.dirichlet_layers: the band of the Dirichlet preconditioner's S_s (0: the whole
  /// interior; decomposition/schur_complements.hpp). auto is 0 here (app::solver_settings
  /// resolves it).
  int dirichlet_layers = 0;
  /// Bytes per rank that dual.operator = auto may give the explicit blocks with the arrays of
  /// forming them (the memory guard's budget less its estimate of the rest of the run:
  /// app/memory_guard.hpp); negative: a quarter of the rank's share of the node's available
  /// memory. At most 4 GiB either way.
  double explicit_block_budget = -1;
  decomposition::GeneralizedInverseMethod generalized_inverse = decomposition::GeneralizedInverseMethod::fixing_dofs;
  /// dual.factor_precision resolved (app::solver_settings; auto is double here).
  la::FactorPrecision factor_precision = la::FactorPrecision::double_precision;
  dual::DualPenaltyOptions dual;
  double search_distance = 0;        ///< 0: automatic (about one master element)
  double linear_contact_band = 0.25; ///< LinearContactRows' band (master face diagonals)
  /// contact.first_rows = reached: from rest, the first outer iteration's rows are those a
  /// rough QP on the rows near contact reaches (FetiContactSolve::rows_reached_from_rest).
  bool first_rows_reached = true;
  /// contact.formulation where given: every pair's formulation; empty: each pair's own.
  std::optional<contact::ContactFormulation> formulation;
  double eps_n_factor;       ///< primal penalty eps_n = factor * max diag K
  FrictionOverride friction; ///< contact.friction.* where given
  /// contact.law = deck: each pair's own normal law; false (hard): hard contact on every pair.
  bool pair_laws = false;

  /// The interaction `pair` is solved with: its own, with the given settings in its place (its
  /// law hard unless pair_laws).
  fem::ContactInteraction interaction(const fem::ContactPairNames& pair) const;
  /// The interaction pair `pair` of `problem` is solved with in step `step` (0-based): as
  /// above, with the friction and law the step gives it (fem::Step::changed_friction,
  /// changed_law) in place of its own.
  fem::ContactInteraction interaction(const fem::Problem& problem, int32_t pair, size_t step) const;
  /// Whether a pair of `problem` is solved with friction in some step.
  bool has_friction(const fem::Problem& problem) const;
  /// Whether pair `pair` of `problem` is solved with friction in some step.
  bool has_friction(const fem::Problem& problem, int32_t pair) const;
  /// Slave nodes of pairs with friction that a linear equation ties to other nodes (any term of
  /// an *EQUATION, the slave of a tie or coupling row). Their normal rows are then linearly
  /// dependent on those rows (fricloop: four slave nodes tied to one z), which leaves the
  /// normal multipliers, and with them the friction bounds, undetermined: the increments of such
  /// a model do not grow (load_history), since the QP does not pass slip reversals from every
  /// state that grown increments reach (docs/usage.md, "Automatic increments").
  int64_t tied_friction_slaves(const fem::Problem& problem) const;
};
} // namespace feticon::nonlinear
