#include "nonlinear/feti_contact_solver.hpp"
#include "nonlinear/linear_contact_rows.hpp"

#include "common/available_memory.hpp"
#include "common/error.hpp"
#include "common/log.hpp"
#include "common/parallel.hpp"
#include "decomposition/constraint_rows.hpp"
#include "decomposition/explicit_boundary_operators.hpp"
#include "decomposition/subdomain_operators.hpp"
#include "contact/coupling_rows.hpp"
#include "contact/tangential_rows.hpp"
#include "dual/contact_qp.hpp"
#include "dual/dual_penalty_problem.hpp"
#include "dual/multiplier_memory.hpp"
#include "fem/temperature_history.hpp"
#include "nonlinear/contact_penalty.hpp"
#include "nonlinear/load_stepping.hpp"
#include "nonlinear/outer_convergence.hpp"
#include "la/vector_space.hpp"
#include "par/block_space.hpp"

#include <algorithm>
#include <numeric>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <functional>
#include <iterator>
#include <set>
#include <utility>
#include <cstdio>

namespace feticon::nonlinear
{
namespace
{
decomposition::Partition make_partition(const fem::Problem& problem, const SolverSettings& s)
{
  const int n = std::max(s.subdomains, problem.mesh.n_bodies());
  if (s.partitioner == Partitioner::metis)
    return decomposition::partition_metis(problem.mesh, n);
  if (s.partitioner == Partitioner::rcb)
    return decomposition::partition_rcb(problem.mesh, n);
  // Structured: split each body along x only (enough for studies; boxes via the API).
  return decomposition::partition_structured(problem.mesh, {std::max(1, s.subdomains / problem.mesh.n_bodies()), 1, 1});
}

/// Reductions over owned stacked vectors: one block per owned subdomain.
par::BlockSpace owned_subdomain_space(const decomposition::Decomposition& decomp)
{
  std::vector<std::vector<la::Index>> blocks;
  std::vector<int64_t> global_index;
  const int64_t base = decomp.global_offset(decomp.first_owned());
  for (int32_t s = decomp.first_owned(); s < decomp.end_owned(); ++s)
  {
    blocks.emplace_back();
    for (int32_t k = 0; k < decomp.subdomain(s).n_dofs(); ++k)
    {
      blocks.back().push_back(static_cast<la::Index>(decomp.offset(s) + k));
      global_index.push_back(base + decomp.offset(s) + k);
    }
  }
  return par::BlockSpace(decomp.comm(), std::move(blocks), std::move(global_index));
}

/// f(dof) for each DOF a contact row has a nonzero on; plane strain's u_z, no unknown and so in
/// no subdomain's B, is skipped (a 2D row's normal has a stored zero there).
template <class F>
void for_each_touched_dof(const fem::Problem& problem, const contact::ContactConstraints& contact_rows, F&& f)
{
  const auto& B = contact_rows.B;
  for (int row = 0; row < B.outerSize(); ++row)
    for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(B, row); it; ++it)
      if (it.value() != 0 && !problem.eliminated[it.col() % 3])
        f(it.col());
}

/// DOFs on the boundary of the Dirichlet preconditioner's Schur complements besides the
/// subdomain interfaces (decomposition/schur_complements.hpp): the supported components, which
/// the Dirichlet rows touch, the linear equations' DOFs, and the contact DOFs the rows may
/// touch. `contact_rows` null: every component of both contact surfaces' nodes. Otherwise the
/// DOFs these rows touch, or, with `all_components`, every component of their nodes (normals
/// turn with large displacements).
/// The fewer contact DOFs, the smaller the dense blocks (|b_s|^2 bytes, |b_s|^3 flops to form)
/// and the better the preconditioner: a DOF no row touches is held fixed in S_s instead of
/// eliminated.
std::vector<char> schur_boundary_dofs(const fem::Problem& problem, const std::vector<int64_t>& held,
                                      const contact::ContactConstraints* contact_rows, bool all_components)
{
  std::vector<char> boundary(3 * static_cast<size_t>(problem.mesh.n_nodes()), 0);
  const int64_t n_global = 3 * int64_t{problem.mesh.n_nodes()};
  const std::vector<fem::DofCombination> combinations = problem.held_combinations();
  for (int64_t dof : held)
    if (dof >= n_global) // a row on every component of the nodes it combines
    {
      for (const int64_t d : combinations.at(static_cast<size_t>(dof - n_global)).dofs)
        for (int c = 0; c < 3; ++c)
          if (!problem.eliminated[c])
            boundary[3 * static_cast<size_t>(d / 3) + c] = 1;
    }
    else if (!problem.eliminated[dof % 3]) // plane strain's u_z = 0 is no row
      boundary[dof] = 1;
  for (const auto* block : {&problem.equations, &problem.tie_equations}) // rows on every copy of these nodes
    for (const fem::LinearEquation& equation : *block)
      for (const auto& term : equation.terms)
        if (!problem.eliminated[term.component])
          boundary[3 * static_cast<size_t>(term.node) + term.component] = 1;
  const auto flag_node = [&](int64_t node) {
    for (int c = 0; c < 3; ++c)
      if (!problem.eliminated[c])
        boundary[3 * node + c] = 1;
  };
  if (!contact_rows)
  {
    for (const auto& pair : problem.contacts)
      for (const std::string& set : {pair.slave, pair.master})
        for (int32_t node : problem.mesh.face_set_nodes(set))
          flag_node(node);
    return boundary;
  }
  for_each_touched_dof(problem, *contact_rows, [&](int64_t dof) {
    if (all_components)
      flag_node(dof / 3);
    else
      boundary[dof] = 1;
  });
  return boundary;
}

/// Whether every DOF the rows touch is flagged in `boundary`.
bool covers(const fem::Problem& problem, const std::vector<char>& boundary,
            const contact::ContactConstraints& contact_rows)
{
  bool all = true;
  for_each_touched_dof(problem, contact_rows, [&](int64_t dof) { all = all && boundary[dof]; });
  return all;
}

/// SolverSettings::explicit_block_budget, or without it a quarter of this rank's share of the
/// node's available memory; at most 4 GiB per rank.
double explicit_block_budget(const SolverSettings& settings)
{
  constexpr double at_most = 4.0 * (1L << 30);
  if (settings.explicit_block_budget >= 0)
    return std::min(settings.explicit_block_budget, at_most);
  return std::min(0.25 * static_cast<double>(available_memory_bytes()) / par::ranks_on_this_node(), at_most);
}

/// dual.operator = auto: explicit when the dense blocks fit the memory left to them on every
/// rank and forming them costs less than they save over the steps the run is expected to
/// take. Memory: a rank's blocks, the arrays of forming them (explicit_forming_bytes) and
/// `held` bytes of older blocks alive meanwhile must fit explicit_block_budget on every rank.
/// Costs in flops of the factor substitutions: an implicit step
/// applies K_s+ and the K_ii solve of S_s once each, about 4 (nnz(L_s) + nnz(L_ii)) ~
/// 8 nnz(L_s); an explicit one two dense products of 2 |b_s|^2, which run at 3 times the
/// flop rate of the substitutions; forming the blocks (one factorization with b_s last and
/// dense LAPACK, about 1.7 |b_s|^3 flops at 4 times that rate) 0.42 |b_s|^3. Expected steps:
/// 150 per load step, with small or large displacements. The rates and the step count are
/// fitted to measured runs (docs/measurements.md, "dual.operator = auto").
std::pair<bool, std::string> choose_explicit(const SolverSettings& settings,
                                             const decomposition::SubdomainSystem& system,
                                             const decomposition::SchurComplements* schur, int n_load_steps,
                                             int64_t held, const par::Communicator& comm)
{
  if (settings.dual_operator == DualOperatorMode::implicit)
    return {false, "dual.operator = implicit"};
  FETICON_CHECK(schur || settings.dual_operator != DualOperatorMode::explicit_,
                "dual.operator = explicit forms the operators on the boundary of the Dirichlet preconditioner; "
                "set qp.preconditioner = dirichlet");
  if (!schur)
    return {false, "no Dirichlet preconditioner, whose boundary the explicit blocks use"};
  if (settings.dual_operator == DualOperatorMode::explicit_)
    return {true, "dual.operator = explicit"};
  if (settings.dirichlet_layers > 0) // the blocks would hold the whole S_s
    return {false,
            "the Dirichlet preconditioner's band (qp.dirichlet_layers = " + std::to_string(settings.dirichlet_layers) +
                ") is applied with its own factors"};
  const auto& decomp = system.decomposition();
  double setup = 0, implicit_step = 0, explicit_step = 0;
  std::vector<double> boundary_sizes;
  for (int32_t s = decomp.first_owned(); s < decomp.end_owned(); ++s)
  {
    const double nb = static_cast<double>(schur->boundary(s).size());
    boundary_sizes.push_back(nb);
    const double substitution = 8.0 * static_cast<double>(system.operators(s).K_plus.factor_nonzeros());
    setup += 0.42 * nb * nb * nb;
    implicit_step += substitution;
    explicit_step += 4 * nb * nb / 3;
  }
  // Each rank against its own budget: the ranks of a node share its memory.
  const int64_t rank_bytes = decomposition::explicit_operator_bytes(system, *schur);
  const double need = static_cast<double>(rank_bytes + held) + explicit_forming_bytes(boundary_sizes, threads());
  const double budget = explicit_block_budget(settings);
  const double worst = comm.max(need - budget);
  const int64_t bytes = comm.sum(rank_bytes);
  const double steps = 150.0 * n_load_steps;
  setup = static_cast<double>(comm.sum(static_cast<int64_t>(setup)));
  implicit_step = static_cast<double>(comm.sum(static_cast<int64_t>(implicit_step)));
  explicit_step = static_cast<double>(comm.sum(static_cast<int64_t>(explicit_step)));
  char reason[256];
  if (worst > 0)
  {
    std::snprintf(reason, sizeof reason,
                  "auto: the dense blocks (%.3g MiB) and forming them exceed their memory budget by %.3g MiB on a rank "
                  "(budget %.3g MiB per rank)",
                  static_cast<double>(bytes) / (1 << 20), worst / (1 << 20), budget / (1 << 20));
    return {false, reason};
  }
  const bool pays = setup + steps * explicit_step < steps * implicit_step;
  std::snprintf(reason, sizeof reason,
                "auto: over %.0f expected steps, explicit %.3g Gflop (set-up %.3g) against implicit %.3g Gflop; "
                "blocks %.3g MiB",
                steps, 1e-9 * (setup + steps * explicit_step), 1e-9 * setup, 1e-9 * steps * implicit_step,
                static_cast<double>(bytes) / (1 << 20));
  return {pays, reason};
}

/// The constants of a pair's law that contact.law = deck solves, checked (a deck's or problem
/// file's reader checks most of them; a table the tangent cannot follow is refused here).
void check_law(const fem::ContactInteraction& interaction, int32_t pair)
{
  const fem::NormalLaw& law = interaction.law;
  const std::string which = "contact pair " + std::to_string(pair + 1) +
      (interaction.name.empty() ? "" : " (interaction " + interaction.name + ")") + ": its " +
      fem::normal_law_name(law.kind) + " law ";
  FETICON_CHECK(law.kind != fem::NormalLawKind::linear || (std::isfinite(law.slope) && law.slope > 0),
                which << "needs a positive slope K (" << law.slope << ")");
  FETICON_CHECK(law.kind != fem::NormalLawKind::exponential || (law.c0 > 0 && law.p0 > 0),
                which << "needs positive c0 and p0 (" << law.c0 << ", " << law.p0 << ")");
  if (law.kind != fem::NormalLawKind::tabular)
    return;
  bool increasing = law.table.size() >= 2;
  for (size_t j = 0; j + 1 < law.table.size(); ++j)
    increasing = increasing && law.table[j + 1].second > law.table[j].second;
  FETICON_CHECK(increasing,
                which << "needs two points or more with increasing pressures (the outer loop follows its "
                         "tangent, which a constant pressure does not have)");
}

std::string format_iteration(const OuterIteration& it)
{
  char line[256];
  std::snprintf(line, sizeof line,
                "step %2d  outer %2d  inner %5d  residual %9.2e  |du|/|u| %9.2e  active %5ld  %7.2f s", it.load_step,
                it.iteration, it.qp.iterations, it.residual_norm, it.displacement_change,
                static_cast<long>(it.active_contacts), it.seconds);
  return line;
}

/// The phases of the FETI contact solve on one problem (run_load_steps drives them).
class FetiContactSolve final : public LoadStepPhases
{
public:
  /// Set-up: decomposition, K_0 and R(X) with their factors, the preconditioner and the
  /// explicit operators (kept for the whole run: modified Newton), f_int(0).
  FetiContactSolve(const fem::Problem& problem, const SolverSettings& settings, TimerTable& timers,
                   par::Communicator comm, ContactSolution& out);

  /// Continues the interrupted run `previous`; returns the first load step to solve.
  int restore(const ContactSolution& previous);

  void begin_load_step(int step, double t) override;
  IterationOutcome outer_iteration(int k, OuterIteration& it) override;
  void end_load_step(const LoadStep& record) override;
  std::string format(const OuterIteration& it) const override { return format_iteration(it); }
  bool cut_back(int step) override;
  fem::LoadHistory& history() { return _history; }

private:
  /// newton.stiffness = auto, the first load step that fails under K_0: the rest of the run
  /// refreshes K_M(u) at every outer iteration and solves each QP to qp.rtol, without the
  /// force tolerance (qp.force_rtol). On a slender body (beamcontact's and contact2's C3D20(R)
  /// beams) K_0's modified Newton contracts slowly once the beam turns, and a QP error of
  /// force_rtol times the load, multiplied by the beam's compliance, is a correction |du|/|u|
  /// of 1e-6 to 1e-5 that no outer iteration goes below: with both changes the two run
  /// (docs/contact.md, "When K_0 fails"). Runs that converge under K_0 are unchanged.
  void escalate(int step);
  /// K, R and their factors at the current u; the preconditioner and explicit blocks with them.
  void update_stiffness();
  /// The Schur complements' boundaries from _schur_boundary, and the K_ii factors or the
  /// explicit blocks on them, for the current K; returns the subdomains whose operators were
  /// formed. `same_K`: K did not change since the last call, so the explicit blocks of a
  /// subdomain whose boundary did not change either are kept.
  int update_boundary_operators(bool same_K);
  /// f_int and its assembled norm at the current u; throws (on every rank) where an element
  /// is inverted at u.
  void update_internal_force();
  /// The subdomains' temperature change at load step `step` (problems with temperatures).
  void set_temperatures(int step);
  /// The pairs in force in load step `step`'s step (the others' rows are not built) and the
  /// interactions they are solved with there (a *CHANGE FRICTION).
  void set_pairs_in_force(int step);
  /// The same where u is an outer iteration's result: an element inverted at u (on any rank)
  /// is the outer loop diverging, which a cutback may cure, not an error of the run; its
  /// message, the same on every rank, is returned and f_int is left as it was.
  std::optional<std::string> update_internal_force_at_iterate();
  /// max(||f(t_n)||, ||f_int(u)||): the scale of the relative residual (OuterConvergence).
  double force_scale() const { return std::max({_f_step_norm, _f_int_norm, _thermal_force_norm, _force_floor}); }
  /// The QP tolerance of outer iteration k (SolverSettings::forcing).
  double qp_rtol(int k);
  /// Rows of the outer loop only where g < max(g_min, 0) + 0.05 master diagonals
  /// (contact::ContactOptions): the fewest MPRGP steps of a sweep from 1 to 0.002 on Hertz and
  /// hertz3d with large displacements (docs/contact.md, "Rows near contact").
  static constexpr double near_contact_fraction = 0.05;
  /// With large displacements, the Schur boundary's contact DOFs: those of the rows within
  /// 0.25 master face diagonals of contact (in the configuration where it is formed), a margin
  /// for the contact to spread into; a row beyond them grows the boundary the same way at the
  /// current u (outer_iteration). The sphere example's blocks: |b_s| at most 1 533 with every
  /// row within the search distance, 1 441 with this reach (docs/contact.md).
  static constexpr double reach_fraction = 0.25;
  /// The rows of the Schur boundary's reach at u (global), for the large-displacement loop.
  contact::ContactConstraints reach_rows(const la::Vector& u_global) const;
  /// Every pair's rows at u (global) with `options` and the pair's formulation, pair after pair.
  contact::ContactConstraints pair_rows_at(const la::Vector& u_global, contact::ContactOptions options) const;
  /// The master face set of each pair, for LinearContactRows.
  std::vector<std::string> master_sets() const;
  /// From rest (u = 0), the first outer iteration's rows: `near` and the rows of the reach that
  /// the answer of a rough QP on `near` (rtol rough_rtol) comes within the band of at rest
  /// (LinearContactRows::expand). The rows near a first touch are a vanishing share of the
  /// contact zone as the mesh is refined (0.05 master diagonals held 100 of hertz3d 924k's 472
  /// rows in contact): the first QP then put the whole load on them, and the outer iterations
  /// after it took most of the run to spread it (docs/contact.md, "The first QP's rows from
  /// rest"). Its
  /// MPRGP steps and products are added to `counters`; its multipliers, SMALBE-M state and
  /// ||PFP|| estimate are remembered, so the iteration's QP starts from them (0 on the rows
  /// added), as one outer iteration's QP starts from the last one's.
  contact::ContactConstraints rows_reached_from_rest(contact::ContactConstraints near, const la::Vector& u_global,
                                                     qp::QpCounters& counters);
  /// The rough QP's tolerance: a few MPRGP steps (3-14 on Hertz, hertz3d and the spheres), enough to show
  /// how far the contact spreads.
  static constexpr double rough_rtol = 0.1;
  /// The dual's rows: the equality rows, then `contact`'s (ids from _n_equality on).
  decomposition::ConstraintRows dual_rows(const contact::ContactConstraints& contact) const;

  // The parts of one outer iteration (ALGORITHMS.md section 8).
  /// Norms of the correction du and of u after it, and ||du||_inf (assembled).
  struct Correction
  {
    double du_norm;
    double u_norm;
    double du_max;
    std::optional<std::string> inverted; ///< an element inverted at the new u (f_int not updated)
  };
  /// The contact rows at u (global): a linear run's rows near contact, otherwise a new search.
  contact::ContactConstraints search_contact(const la::Vector& u_global) const;
  /// The Schur boundary grown by the reach at u, and the operators of the subdomains it changed.
  void grow_schur_boundary(const la::Vector& u_global, const std::string& where);
  /// G, GG' and the FETI operators for the rows of this iteration.
  std::unique_ptr<dual::FetiOperators> coarse_problem(const decomposition::ConstraintRows& rows) const;
  /// The owned right-hand sides c of the rows: targets less B_E u for the equalities, gaps for contact.
  la::Vector constraint_values(const dual::FetiOperators& feti, const decomposition::ConstraintRows& rows) const;
  /// The dual QP's options at outer iteration k: its rtol and, for an exact QP, the feasibility tolerance.
  dual::DualPenaltyOptions qp_options(int k);
  /// The QP's counters, the relative correction and the force residual at the new u in `it`
  /// (f_int updated on the way); returns the norms the convergence test needs.
  Correction measure_iteration(const dual::FetiOperators& feti, const dual::DualSolution& solution, OuterIteration& it);
  /// The contact rows and multipliers into the solution; true if a linear run must add
  /// penetrated rows left out of this QP and solve again.
  bool store_contact_result(const dual::DualSolution& solution, contact::ContactConstraints contact_rows,
                            const la::Vector& contact_lambda, const std::string& where);
  /// With friction: the tangential rows of `contact_rows` appended to `rows` with c_T = the
  /// negative slip since the load step began (none without friction, and for Coulomb's first
  /// QP of a run, which has no normal force yet).
  contact::TangentialRows friction_rows(const contact::ContactConstraints& contact_rows, const la::Vector& u_global,
                                        decomposition::ConstraintRows& rows) const;
  /// The slip bound of each owned tangential row: Tresca's g D_j, or mu times the last normal force.
  std::optional<dual::FrictionRows> slip_bounds(const dual::FetiOperators& feti,
                                                const contact::ContactConstraints& contact_rows,
                                                const contact::TangentialRows& tangential) const;
  /// The compliance of each owned normal row whose pair's law is a penalty spring (dual/contact_qp.hpp),
  /// 0 on the others, and the overclosure at which its pressure starts added to its c (the law's
  /// tangent at the row's gap, fem::NormalLaw::tangent); none (c unchanged) where every pair is hard.
  std::optional<la::Vector> law_compliance(const dual::FetiOperators& feti,
                                           const contact::ContactConstraints& contact_rows, la::Vector& c) const;
  /// Coulomb: whether the normal forces, and so the slip bounds, changed by at most the
  /// displacement tolerance in the last QP (always true otherwise).
  bool friction_settled(const std::map<int64_t, double>& normal_before,
                        const contact::TangentialRows& tangential) const;
  /// The warning of a step that ends at the floor of the QP's equilibrium error.
  std::string floor_message(const OuterIteration& it, double du_max, double feasibility_error) const;
  OuterVerdict linear_verdict(bool more_rows, double residual);

  const fem::Problem& _problem;
  const SolverSettings& _settings;
  TimerTable& _timers;
  ContactSolution& _out;
  /// Small displacements: the contact rows are a fixed set of candidates found at the reference
  /// configuration (LinearContactRows).
  const bool _small_displacements;
  /// A linear problem (small displacements, elastic bodies): one solve per load step, its outer
  /// loop the contact set's (linear_verdict). A plastic body's f_int is nonlinear in u even at
  /// small strain: its outer loop is the modified Newton loop of large displacements.
  const bool _linear;
  StiffnessUpdate _stiffness; ///< SolverSettings::stiffness_of the problem, until escalate()
  /// The run left K_0 for K_M(u) refreshed at every outer iteration and QPs to qp.rtol alone
  /// (escalate).
  bool _escalated = false;
  fem::LoadHistory _history; ///< split where a load step is cut back
  std::unique_ptr<decomposition::Decomposition> _decomp;
  par::BlockSpace _primal_space;
  std::unique_ptr<decomposition::SubdomainSystem> _system;
  /// The DOFs some step holds (the Dirichlet rows' DOFs are on the Schur boundary in every step),
  /// and those the current load step's holds (unset before the first).
  const std::vector<int64_t> _ever_held;
  std::optional<std::vector<int64_t>> _held;
  std::vector<int32_t> _ties_out; ///< the ties out of force in the current load step's step
  /// The current load step's held DOFs and values (its equality rows' target).
  fem::ConstrainedDofs _target;
  /// Large displacements turn rank-6 kinematic couplings by finite rotations: their rows are
  /// linearized again at every outer iteration (contact/coupling_rows.hpp).
  bool _finite_couplings = false;
  std::vector<char> _schur_boundary; ///< empty without the Dirichlet preconditioner
  std::unique_ptr<decomposition::SchurComplements> _schur;
  std::unique_ptr<decomposition::ExplicitBoundaryOperators> _explicit_operators;
  std::vector<la::Vector> _f_terms_stacked; ///< the forces of the history's terms, stacked
  OuterConvergence _convergence;
  /// A force at round-off: what a round-off displacement (1e-9 L) costs at the stiffest DOF of
  /// K_0. The residual's scale and the contact set's threshold do not go below it, so that an
  /// unloaded model, whose loads, forces and multipliers are all round-off, converges.
  double _force_floor = 0;
  /// Every contact pair, and the interaction each is solved with (SolverSettings::interaction).
  std::vector<contact::ContactPair> _pairs;
  std::vector<char> _pair_in_force; ///< per pair, in the current load step's step (*MODEL CHANGE)
  std::vector<fem::ContactInteraction> _interactions;
  bool _friction = false; ///< some pair has friction: every contact row gets its tangential rows
  contact::ContactOptions _contact_options;
  /// A linear run's rows: the candidates at the reference configuration (found at set-up,
  /// also for the Schur boundary) and the subset near contact that its QPs get.
  std::optional<LinearContactRows> _linear_rows;

  la::Vector _u;          ///< stacked displacement of the owned subdomains
  la::Vector _f_int;      ///< internal force at _u, kept up to date after every update
  double _f_int_norm = 0; ///< ||f_int|| assembled over the subdomains, with _f_int
  /// Warm start of the next QP. Without SMALBE-M's equality multiplier the next QP starts
  /// with the full gradient of the bound multipliers' coarse part and rebuilds it over ~10
  /// outer iterations (docs/measurements.md: it halves the MPRGP steps of large Hertz).
  dual::MultiplierMemory _multipliers;
  std::set<int64_t> _previous_active; ///< keys (pair, slave node) of the active rows, last iteration
  double _previous_residual = 0;      ///< the relative residual of the last outer iteration

  // The current load step.
  int _step = 0;
  la::Vector _f_step; ///< f(t_n), stacked
  const fem::TemperatureHistory _temperatures;
  la::Vector _temperature_change; ///< T - T_0 per mesh node at the current load step; empty: none
  /// ||f_int(0)|| at the current temperatures, assembled: the load of the thermal strain on a
  /// held body, the force scale of a run loaded by temperatures alone (f_int of its answer is 0).
  double _thermal_force_norm = 0;
  double _f_step_norm = 0; ///< ||f(t_n)|| (fem::LoadHistory::external_force_norm)
  std::unique_ptr<decomposition::EqualityRows> _equality;
  int64_t _n_equality = 0;
  bool _forcing = false;
  bool _diverged = false;
  la::Vector _equality_by_id; ///< for the checkpoint of a converged step
  la::Vector _u_step_start;   ///< global u at the start of the load step (the slip's origin)
  /// What the load step started from, for a cutback (cut_back): u, the multipliers that
  /// warm-started its first QP and the active set they had.
  struct StepStart
  {
    la::Vector u;
    dual::MultiplierMemory multipliers;
    std::set<int64_t> active;
  } _step_start;
  /// A cutback restored u after K_M(u) was refreshed at a later u (newton.stiffness =
  /// iteration): the next outer iteration refreshes it at the restored u.
  bool _stiffness_stale = false;
};

FetiContactSolve::FetiContactSolve(const fem::Problem& problem, const SolverSettings& settings, TimerTable& timers,
                                   par::Communicator comm, ContactSolution& out)
    : _problem(problem), _settings(settings), _timers(timers), _out(out),
      _small_displacements(settings.kinematics == fem::Kinematics::linear), _linear(settings.path_independent(problem)),
      _stiffness(settings.stiffness_of(problem)), _history(settings.load_history(problem)), _decomp([&] {
        ScopedTimer t(timers, "decomposition");
        return std::make_unique<decomposition::Decomposition>(problem.mesh, make_partition(problem, settings),
                                                              problem.eliminated, comm);
      }()),
      _primal_space(owned_subdomain_space(*_decomp)),
      _system(std::make_unique<decomposition::SubdomainSystem>(
          *_decomp, problem.materials, settings.kinematics, settings.generalized_inverse, settings.factor_precision)),
      _ever_held(_history.dofs()), _temperatures(problem)
{
  _out.n_subdomains = _decomp->n_subdomains();
  _finite_couplings = !_small_displacements && problem.has_finite_couplings();
  for (const int stage : _history.stages_in_one_step())
    log::info("step " + std::to_string(stage) +
              " asks for several increments and takes one: with small displacements, elastic bodies and no "
              "friction its answer does not depend on the load path");
  if (_history.has_automatic_increments())
    if (const int64_t tied = settings.tied_friction_slaves(problem); tied > 0)
      log::warning(std::to_string(tied) +
                   " slave nodes of pairs with friction are tied by equations (*EQUATION, a tie "
                   "or a coupling), which leaves their normal multipliers undetermined: the automatic increments "
                   "stay at their initial size (cut back where one fails) instead of growing after easy ones");
  if (!comm.serial())
  {
    for (int32_t s = _decomp->first_owned(); s < _decomp->end_owned(); ++s)
    {
      const auto& cells = _decomp->subdomain(s).domain.cells;
      _out.owned_cells.insert(_out.owned_cells.end(), cells.begin(), cells.end());
    }
    std::sort(_out.owned_cells.begin(), _out.owned_cells.end());
  }
  _u = la::Vector::Zero(_decomp->n_primal());
  _out.plastic = fem::MeshPlasticStates::zero(problem.mesh, problem.materials);
  for (int32_t p = 0; p < std::ssize(problem.contacts); ++p)
  {
    const fem::ContactPairNames& pair = problem.contacts[p];
    _pairs.push_back({pair.slave, pair.master, pair.slave_nodes});
    _interactions.push_back(settings.interaction(problem, p, 0));
  }
  // A pair that gets friction in a later step (*CHANGE FRICTION) needs tangential rows from the
  // start, with the bound 0 until then.
  _friction = settings.has_friction(problem);
  _pair_in_force.assign(_pairs.size(), 1);
  _contact_options.search_distance = settings.search_distance;
  const bool dirichlet = settings.dual.preconditioner == dual::DualPreconditioner::dirichlet;
  if (dirichlet || _small_displacements)
  {
    // In the reference configuration: a linear run's candidates, every row within the search
    // distance (LinearContactRows picks its QPs' rows among them); with large displacements,
    // the rows near contact (reach_fraction), which a later row beyond them grows
    // (outer_iteration).
    ScopedTimer t(timers, "contact search");
    const la::Vector zero = la::Vector::Zero(3 * problem.mesh.n_nodes());
    contact::ContactConstraints reach = _small_displacements ? pair_rows_at(zero, _contact_options) : reach_rows(zero);
    if (dirichlet)
      _schur_boundary = schur_boundary_dofs(problem, _ever_held, &reach, !_small_displacements || _friction);
    if (_small_displacements)
      _linear_rows.emplace(problem.mesh, master_sets(), std::move(reach), settings.linear_contact_band);
  }
  update_stiffness(); // K_0 and R(X), kept for the whole run (modified Newton)
  for (const fem::LoadTerm& term : _history.terms())
    _f_terms_stacked.push_back(_decomp->scatter_split(term.force));
  const Eigen::Vector3d extent = problem.mesh.nodes.colwise().maxCoeff() - problem.mesh.nodes.colwise().minCoeff();
  _convergence = {settings.displacement_tolerance, settings.residual_tolerance, extent.norm()};
  double stiffest = 0;
  for (int32_t s = 0; s < _system->n_subdomains(); ++s)
    if (_system->operators(s).K.size() > 0)
      stiffest = std::max(stiffest, _system->operators(s).K.diagonal().cwiseAbs().maxCoeff());
  _force_floor = _primal_space.max(stiffest) * _convergence.roundoff_displacement();
  // The outer loop rebuilds the rows at every iteration, so rows near contact suffice; a linear
  // run solves once and needs every node within the search distance.
  if (!_small_displacements)
    _contact_options.near_contact_fraction = near_contact_fraction;
  ScopedTimer t(timers, "internal forces");
  update_internal_force();
}

void FetiContactSolve::update_stiffness()
{
  // Blocks of the old K are of no use: freed before K is factorized and the new ones are
  // formed, so that a refresh does not hold two sets at its peak.
  _explicit_operators.reset();
  _system->update(_u, &_timers);
  update_boundary_operators(false);
}

contact::ContactConstraints FetiContactSolve::reach_rows(const la::Vector& u_global) const
{
  contact::ContactOptions options = _contact_options;
  options.near_contact_fraction = reach_fraction;
  return pair_rows_at(u_global, options);
}

contact::ContactConstraints FetiContactSolve::pair_rows_at(const la::Vector& u_global,
                                                           contact::ContactOptions options) const
{
  std::vector<contact::ContactConstraints> parts;
  for (size_t p = 0; p < _pairs.size(); ++p)
  {
    options.formulation = _interactions[p].formulation;
    if (_pair_in_force[p])
      parts.push_back(contact::build_contact_constraints(_problem.mesh, u_global, _pairs[p], options));
    else
      parts.push_back(contact::no_rows(options.formulation, 3 * static_cast<la::Index>(_problem.mesh.n_nodes())));
  }
  return contact::concatenate_pairs(std::move(parts), 3 * static_cast<la::Index>(_problem.mesh.n_nodes()));
}

std::vector<std::string> FetiContactSolve::master_sets() const
{
  std::vector<std::string> out;
  for (const contact::ContactPair& pair : _pairs)
    out.push_back(pair.master);
  return out;
}

contact::ContactConstraints FetiContactSolve::rows_reached_from_rest(contact::ContactConstraints near,
                                                                     const la::Vector& u_global,
                                                                     qp::QpCounters& counters)
{
  const decomposition::ConstraintRows rows = dual_rows(near);
  const std::unique_ptr<dual::FetiOperators> feti = coarse_problem(rows);
  const la::Vector c = constraint_values(*feti, rows);
  const qp::QpState warm = _multipliers.warm_start(*feti, _n_equality, near.keys(), 0);
  dual::DualPenaltyOptions options = qp_options(1);
  options.rtol = std::max(options.rtol, rough_rtol);
  dual::DualSolution rough;
  {
    ScopedTimer t(_timers, "dual solve (MPRGP)");
    rough = dual::solve_contact_dual(*feti, c, _f_step - _f_int, _n_equality, options, warm, nullptr);
  }
  counters += rough.report;
  if (!rough.report.converged)
    return near;
  _multipliers.remember(*feti, rough, _n_equality, near.keys());
  // Candidates: the reach, the rows the Schur boundary was made for.
  LinearContactRows reached(_problem.mesh, master_sets(), reach_rows(u_global), near_contact_fraction);
  if (!reached.expand(_decomp->gather_mean(_decomp->gather_stacked(rough.u))))
    return near;
  return reached.selected_rows(la::Vector());
}

decomposition::ConstraintRows FetiContactSolve::dual_rows(const contact::ContactConstraints& contact) const
{
  decomposition::ConstraintRows rows = _equality->rows;
  rows.append(decomposition::rows_from_global(*_decomp, contact.B, contact.c), _n_equality);
  return rows;
}

int FetiContactSolve::update_boundary_operators(bool same_K)
{
  // Of the same K (a grown boundary) the unchanged subdomains' blocks are kept, and the others
  // live until the new ones are formed (counted in the budget); of another K none are left.
  if (!same_K)
    _explicit_operators.reset();
  if (!_schur_boundary.empty()) // the boundaries first: the choice below depends on their sizes
    _schur =
        std::make_unique<decomposition::SchurComplements>(*_system, _schur_boundary, false, _settings.dirichlet_layers);
  int64_t held = 0; // the old blocks of the subdomains to be formed again
  if (_explicit_operators)
    for (int32_t s = _decomp->first_owned(); s < _decomp->end_owned(); ++s)
      if (_explicit_operators->boundary(s) != _schur->boundary(s))
      {
        const auto nb = static_cast<int64_t>(_explicit_operators->boundary(s).size());
        held += static_cast<int64_t>(sizeof(double)) * (nb * nb + nb);
      }
  const auto [use_explicit, reason] =
      choose_explicit(_settings, *_system, _schur.get(), _history.n_steps(), held, _decomp->comm());
  if (!use_explicit)
  {
    _explicit_operators.reset();
    _out.explicit_operator_bytes = 0;
  }
  if (_schur && !use_explicit)
  {
    ScopedTimer t(_timers, "preconditioner setup"); // K_ii factorizations for the implicit S_s
    _schur->factorize_interior();
  }
  _out.dual_operator = use_explicit ? "explicit" : "implicit";
  _out.dual_operator_reason = reason;
  log::info("dual operators: " + _out.dual_operator + " (" + reason + ")");
  std::unique_ptr<decomposition::ExplicitBoundaryOperators> previous = std::move(_explicit_operators);
  if (!use_explicit)
    return _decomp->n_subdomains();
  ScopedTimer t(_timers, "explicit operators");
  _explicit_operators =
      std::make_unique<decomposition::ExplicitBoundaryOperators>(*_system, *_schur, same_K ? previous.get() : nullptr);
  _out.explicit_operator_bytes = _decomp->comm().sum(_explicit_operators->bytes());
  return static_cast<int>(_decomp->comm().sum(static_cast<int64_t>(_explicit_operators->formed())));
}

int FetiContactSolve::restore(const ContactSolution& previous)
{
  const RestartState& r = previous.restart;
  FETICON_CHECK(r.u_stacked.size() == _decomp->n_primal_global(),
                "restart: the checkpoint has " << r.u_stacked.size() << " unknowns, this problem "
                                               << _decomp->n_primal_global() << " (different mesh or subdomains?)");
  std::vector<fem::LoadHistory::Done> done; // of a run that cut steps back or grew them: the same plan
  for (int i = 0; i < r.completed_steps && i < static_cast<int>(previous.steps.size()); ++i)
    done.push_back(done_of(previous.steps[i]));
  _history.follow(done);
  FETICON_CHECK(r.completed_steps < _history.n_steps(),
                "restart: all " << _history.n_steps() << " load steps are already done");
  // The step numbers name points of the load history: a checkpoint of other load_steps or
  // stages would continue at the wrong load.
  const double saved_t = static_cast<int>(previous.steps.size()) >= r.completed_steps
      ? previous.steps[r.completed_steps - 1].load_factor
      : std::nan("");
  FETICON_CHECK(std::abs(saved_t - _history.load_factor(r.completed_steps)) <= 1e-12 * r.completed_steps,
                "restart: the checkpoint's load step " << r.completed_steps << " is at load factor " << saved_t
                                                       << ", this run's at " << _history.load_factor(r.completed_steps)
                                                       << " (different load_steps or load stages?)");
  const int stage = _history.point(r.completed_steps).stage;
  if (!r.stage_start.empty())
    _history.set_start_values(stage, Eigen::Map<const la::Vector>(r.stage_start.data(), std::ssize(r.stage_start)));
  _held = _history.held_dofs(stage);
  _ties_out = _problem.steps[stage - 1].removed_ties;
  _u = _decomp->owned_slice(r.u_stacked);
  std::vector<int64_t> keys;
  for (size_t j = 0; j < r.contact_slave.size(); ++j)
  {
    FETICON_CHECK(r.contact_pair.empty() || (r.contact_pair[j] >= 0 && r.contact_pair[j] < std::ssize(_pairs)),
                  "restart: the checkpoint names contact pair " << r.contact_pair[j] << ", this problem has "
                                                                << _pairs.size() << " (another model?)");
    keys.push_back(contact::contact_key(r.contact_pair.empty() ? 0 : r.contact_pair[j], r.contact_slave[j]));
  }
  _multipliers.restore(r.dual, keys, r.contact_lambda, r.contact_tangential);
  if (_linear_rows && !r.linear_rows_selected.empty())
    _linear_rows->select(r.linear_rows_selected);
  _previous_active = _multipliers.active_keys(_force_floor);
  if (!r.schur_boundary.empty() && _schur) // the boundary had grown: its operators as they were
  {
    for (const int32_t dof : r.schur_boundary)
    {
      FETICON_CHECK(dof >= 0 && static_cast<size_t>(dof) < _schur_boundary.size(),
                    "restart: the checkpoint's Schur boundary names DOF " << dof << " of " << _schur_boundary.size());
      _schur_boundary[dof] = 1;
    }
    _out.schur_boundary_widened = true;
    update_boundary_operators(true);
  }
  _out.history = previous.history;
  _out.steps = previous.steps;
  _out.warnings = previous.warnings; // the floors of the steps before the checkpoint
  if (!_out.plastic.empty())
  {
    FETICON_CHECK(!r.plastic.empty(),
                  "restart: the checkpoint holds no plastic states, and a body of this problem "
                  "is plastic (another model?)");
    _out.plastic.unpack(r.plastic);
    _system->set_plastic_states(_out.plastic);
  }
  set_temperatures(r.completed_steps);
  if (r.escalated)
    escalate(0);
  ScopedTimer t(_timers, "internal forces");
  update_internal_force();
  // A refreshed K_M(u) is rebuilt at the first outer iteration of the step, as it would
  // have been in the uninterrupted run.
  return r.completed_steps + 1;
}

void FetiContactSolve::begin_load_step(int step, double)
{
  _step = step;
  set_pairs_in_force(step);
  _u_step_start = _decomp->gather_mean(_decomp->gather_stacked(_u));
  // A DOF the step holds and the step before left free ramps from its displacement here.
  _history.start_stage(step, _problem.extended(_u_step_start)); // held combinations too
  fem::ConstrainedDofs target = _history.prescribed(step);
  const size_t stage = _history.point(step).stage - 1;
  const std::vector<int32_t>& ties_out = _problem.steps[stage].removed_ties;
  if (_held && (*_held != target.dofs || _ties_out != ties_out))
    _multipliers.forget_equality(); // other Dirichlet or tie rows: the old multipliers are not theirs
  _held = target.dofs;
  _ties_out = ties_out;
  _f_step = _history.combine(step, _f_terms_stacked);
  _f_step_norm = _history.external_force_norm(step);
  _target = target;
  _equality = std::make_unique<decomposition::EqualityRows>(decomposition::build_equality_rows(
      *_decomp, target, _problem.equations, _problem.tie_equations_in_force(stage), _problem.held_combinations()));
  _n_equality = _equality->n_global();
  _forcing = !_linear && _settings.forcing > 0;
  _previous_residual = std::numeric_limits<double>::infinity();
  _equality_by_id.resize(0);
  _step_start = {_u, _multipliers, _previous_active};
  if (!_temperatures.empty())
  {
    // The step's temperatures change f_int(u) at the u it starts from.
    set_temperatures(step);
    ScopedTimer t(_timers, "internal forces");
    update_internal_force();
  }
}

void FetiContactSolve::set_pairs_in_force(int step)
{
  const size_t stage = _history.point(step).stage - 1;
  _pair_in_force.assign(_pairs.size(), 1);
  for (const int32_t p : _problem.steps[stage].removed_contacts)
    _pair_in_force[p] = 0;
  for (int32_t p = 0; p < std::ssize(_pairs); ++p)
  {
    _interactions[p] = _settings.interaction(_problem, p, stage);
    check_law(_interactions[p], p);
  }
  if (_linear_rows)
    _linear_rows->set_pairs_in_force(_pair_in_force);
}

void FetiContactSolve::set_temperatures(int step)
{
  if (_temperatures.empty())
    return;
  _temperature_change = _temperatures.change(_history.point(step));
  _system->set_temperature_change(_temperature_change);
  const la::Vector f_held = _system->internal_force(la::Vector::Zero(_u.size()));
  _thermal_force_norm = _decomp->gather_sum(_decomp->gather_stacked(f_held)).norm();
}

bool FetiContactSolve::cut_back(int step)
{
  if (_linear)
    return false; // one load step, whose outer loop is the contact set's: a smaller one is no easier
  escalate(step);
  _u = _step_start.u;
  _multipliers = _step_start.multipliers;
  _previous_active = _step_start.active;
  _diverged = false;
  _stiffness_stale = _stiffness == StiffnessUpdate::iteration;
  _history.split(step);
  ScopedTimer t(_timers, "internal forces");
  update_internal_force();
  return true;
}

void FetiContactSolve::escalate(int step)
{
  if (!_settings.stiffness_auto || _escalated || _stiffness == StiffnessUpdate::iteration)
    return;
  _escalated = true;
  _stiffness = StiffnessUpdate::iteration;
  _stiffness_stale = true;
  if (step == 0)
    return; // a restart: the run's warnings hold the first run's line
  const std::string warning = "load step " + std::to_string(step) +
      " failed with K_0 (the cutback below says why): from here on K_M(u) is refreshed at every outer iteration "
      "and each QP is solved to qp.rtol (newton.stiffness = auto)";
  log::warning(warning);
  _out.warnings.push_back(warning);
}

void FetiContactSolve::update_internal_force()
{
  if (const std::optional<std::string> inverted = update_internal_force_at_iterate())
    throw Error(*inverted);
}

std::optional<std::string> FetiContactSolve::update_internal_force_at_iterate()
{
  std::string inverted;
  la::Vector f_int;
  try
  {
    f_int = _system->internal_force(_u);
  }
  catch (const Error& e)
  {
    inverted = e.what();
  }
  // Every rank learns of the lowest rank's inverted element, and stops with it.
  const par::Communicator& comm = _decomp->comm();
  const double first = comm.min(inverted.empty() ? comm.size() : comm.rank());
  if (first < comm.size())
  {
    std::vector<int64_t> text;
    if (comm.rank() == static_cast<int>(first))
      text.assign(inverted.begin(), inverted.end());
    const std::vector<int64_t> gathered = comm.all_gather(text); // that rank's message alone
    return std::string(gathered.begin(), gathered.end());
  }
  _f_int = std::move(f_int);
  _f_int_norm = _decomp->gather_sum(_decomp->gather_stacked(_f_int)).norm();
  return std::nullopt;
}

double FetiContactSolve::qp_rtol(int k)
{
  // Inexact QPs while the outer iteration contracts; once a correction grows, the QP errors
  // are being amplified: exact QPs for the rest of the step.
  const auto& history = _out.history;
  if (k > 2 && history.back().displacement_change >= history.rbegin()[1].displacement_change)
    _forcing = false;
  if (!_forcing)
    return _settings.dual.rtol;
  const double forced = k == 1
      ? _settings.max_forcing_rtol
      : std::min(_settings.max_forcing_rtol, _settings.forcing * history.back().displacement_change);
  return std::max(_settings.dual.rtol, forced);
}

IterationOutcome FetiContactSolve::outer_iteration(int k, OuterIteration& it)
{
  const std::string where = "load step " + std::to_string(_step) + ", outer iteration " + std::to_string(k) + ": ";
  // With small displacements K_0 is K for good, unless a plastic body's tangent changes it.
  const bool refresh = (!_small_displacements || !_out.plastic.empty()) &&
      ((_stiffness == StiffnessUpdate::load_step && k == 1 && _step > 1) ||
       (_stiffness == StiffnessUpdate::iteration && (_step > 1 || k > 1)) || _stiffness_stale);
  if (refresh)
  {
    _stiffness_stale = false;
    update_stiffness(); // K_M(u) and R(X + u)
    _multipliers.forget_operator_norm();
  }
  const la::Vector u_global = _decomp->gather_mean(_decomp->gather_stacked(_u));
  if (_finite_couplings)
  {
    // The couplings' rows at this iterate (the same rows, so the same ids and count).
    const size_t stage = _history.point(_step).stage - 1;
    contact::CouplingLinearization now =
        contact::linearize_couplings(_problem, _problem.tie_equations_in_force(stage), u_global);
    _equality = std::make_unique<decomposition::EqualityRows>(
        decomposition::build_equality_rows(*_decomp, _target, _problem.equations, now.ties, now.held));
  }
  contact::ContactConstraints contact_rows = search_contact(u_global);
  qp::QpCounters rough_counters;
  if (_settings.first_rows_reached && !_small_displacements && k == 1 && u_global.isZero(0.0) &&
      contact_rows.n_rows() > 0)
    contact_rows = rows_reached_from_rest(std::move(contact_rows), u_global, rough_counters);
  if (_schur && !covers(_problem, _schur_boundary, contact_rows))
    grow_schur_boundary(u_global, where);
  const la::Vector residual = _f_step - _f_int;
  decomposition::ConstraintRows rows = dual_rows(contact_rows);
  contact::TangentialRows tangential = friction_rows(contact_rows, u_global, rows);

  const std::unique_ptr<dual::FetiOperators> feti = coarse_problem(rows);
  la::Vector c = constraint_values(*feti, rows);
  const std::optional<dual::FrictionRows> friction = slip_bounds(*feti, contact_rows, tangential);
  const std::optional<la::Vector> compliance = law_compliance(*feti, contact_rows, c);
  const std::vector<int64_t> keys = contact_rows.keys();
  const qp::QpState warm = _multipliers.warm_start(*feti, _n_equality, keys, tangential.n_tangents);
  const dual::DualPenaltyOptions dual_options = qp_options(k);
  const std::map<int64_t, double> normal_before = _multipliers.contact();
  dual::DualSolution solution;
  {
    ScopedTimer t(_timers, "dual solve (MPRGP)");
    solution = dual::solve_contact_dual(*feti, c, residual, _n_equality, dual_options, warm,
                                        friction ? &*friction : nullptr, compliance ? &*compliance : nullptr);
  }
  _u += solution.u;
  const la::Vector contact_lambda =
      _multipliers.remember(*feti, solution, _n_equality, keys, tangential.n_tangents, &_out.tangential_lambda);
  const bool slip_bound_settled = friction_settled(normal_before, tangential);
  _out.tangential = std::move(tangential);
  std::set<int64_t> active = _multipliers.active_keys(_force_floor);

  const Correction correction = measure_iteration(*feti, solution, it);
  it.qp += rough_counters;
  // A diverging outer loop shows as a non-finite residual before anything else fails; the
  // iteration is no result, so it stays out of the history (no NaN in history.csv).
  if (correction.inverted)
  {
    _diverged = true;
    return IterationOutcome::diverged(where + "the outer loop diverged: " + *correction.inverted);
  }
  if (!std::isfinite(it.residual_norm) || !std::isfinite(it.displacement_change))
  {
    _diverged = true;
    return IterationOutcome::diverged(where +
                                      "the outer loop diverged (non-finite residual): use more "
                                      "load_steps or newton.stiffness=iteration");
  }
  const bool more_rows = store_contact_result(solution, std::move(contact_rows), contact_lambda, where);
  _out.n_dual = feti->n_dual_global();
  _out.n_kernel = feti->n_kernel();
  _out.feasibility_error = solution.feasibility_error;
  if (!solution.report.converged)
    return IterationOutcome::stop(where + solution.report.reason);
  // The multipliers are the answer (pressures), and an inexact QP leaves them off by far
  // more than its tolerance suggests (that is relative to ||b||, which the gaps of the
  // inactive rows dominate: Hertz at refinement 1 stopped after a QP at rtol 1e-7 had a
  // peak pressure 14 % high). So a step ends only after a QP solved to qp.rtol; if the
  // test passes after a forced one, the next QP, warm-started at the answer, is exact.
  const bool exact_qp = dual_options.rtol <= _settings.dual.rtol;
  const OuterVerdict verdict = _linear
      ? linear_verdict(more_rows, it.residual_norm)
      : _convergence.verdict(correction.du_norm, correction.u_norm, correction.du_max, it.residual_norm, active,
                             _previous_active, std::exchange(_previous_residual, it.residual_norm));
  _previous_active = std::move(active);
  if (verdict == OuterVerdict::iterate || !slip_bound_settled || more_rows)
    return IterationOutcome::next();
  if (!exact_qp) // the step ends only after a QP solved to qp.rtol
  {
    _forcing = false;
    return IterationOutcome::next();
  }
  _equality_by_id = dual::multipliers_by_id(*feti, solution.state.x, 0, _n_equality);
  if (verdict == OuterVerdict::converged)
    return IterationOutcome::step_converged();
  return IterationOutcome::step_at_floor(floor_message(it, correction.du_max, solution.feasibility_error));
}

contact::TangentialRows FetiContactSolve::friction_rows(const contact::ContactConstraints& contact_rows,
                                                        const la::Vector& u_global,
                                                        decomposition::ConstraintRows& rows) const
{
  if (!_friction)
    return {};
  contact::TangentialRows tangential =
      contact::build_tangential_rows(contact_rows, _problem.eliminated, *_held, &_problem.frames);
  // c_T = -B_T (u - u_0): B_T du - c_T is then the slip since the last converged load step.
  const la::Vector c_T = -(tangential.B * (u_global - _u_step_start));
  rows.append(decomposition::rows_from_global(*_decomp, tangential.B, c_T), _n_equality + contact_rows.n_rows());
  return tangential;
}

std::optional<dual::FrictionRows> FetiContactSolve::slip_bounds(const dual::FetiOperators& feti,
                                                                const contact::ContactConstraints& contact_rows,
                                                                const contact::TangentialRows& tangential) const
{
  if (tangential.n_tangents == 0)
    return std::nullopt;
  // Row-normalized bounds: a tangential row has the norm |b| of its normal row, so the force
  // bound g (N) is g |b| in the multiplier's units; Coulomb's mu lambda_N is mu lambda_hat_N.
  // Coulomb's bound is mu times the normal force of the last QP; the first QP of a run has
  // none and sticks everywhere (infinite bound): without friction, or with bound 0, a body
  // that only friction holds along the interface would be free. Tresca's g acts where the last
  // QP had contact (everywhere in the first), not on rows whose bodies are apart. A pair
  // without friction has the bound 0 (where another pair has friction, its rows have
  // tangential rows too).
  const bool first_qp = _multipliers.contact().empty();
  const std::set<int64_t> touching = _multipliers.active_keys(_force_floor);
  const int64_t n_contact = contact_rows.n_rows();
  dual::FrictionRows out{n_contact, la::Vector::Zero(feti.n_dual()), tangential.n_tangents,
                         std::vector<char>(feti.n_dual(), 0)};
  for (la::Index i = 0; i < feti.n_dual(); ++i)
  {
    const int64_t j = feti.row_id(i) - _n_equality - n_contact;
    if (j < 0)
      continue;
    out.held[i] = tangential.held[j];
    const int64_t row = j / tangential.n_tangents;
    const Friction& friction = _interactions[contact_rows.pair[row]].friction;
    if (friction.model == FrictionModel::tresca)
      out.slip_bound(i) = first_qp || touching.count(contact_rows.key(row))
          ? friction.slip_bound * contact_rows.slave_area[row] * contact_rows.row_norm[row]
          : 0.0;
    else if (friction.model == FrictionModel::none)
      out.slip_bound(i) = 0;
    else if (first_qp)
      out.slip_bound(i) = std::numeric_limits<double>::infinity();
    else if (const auto it = _multipliers.contact().find(contact_rows.key(row)); it != _multipliers.contact().end())
      out.slip_bound(i) = friction.coefficient * std::max(it->second, 0.0);
  }
  return out;
}

std::optional<la::Vector> FetiContactSolve::law_compliance(const dual::FetiOperators& feti,
                                                           const contact::ContactConstraints& contact_rows,
                                                           la::Vector& c) const
{
  if (std::ranges::all_of(_interactions, [](const fem::ContactInteraction& interaction) {
        return interaction.law.kind == fem::NormalLawKind::hard;
      }))
    return std::nullopt;
  // The law's spring on the row (row_spring): B_i du - (c_i + shift_i) = lambda_i / stiffness_i.
  la::Vector out = la::Vector::Zero(feti.n_dual());
  double unusable = 0; // the pair (from 1) of a row whose law gives no finite compliance
  for (la::Index i = 0; i < feti.n_dual(); ++i)
  {
    const int64_t row = feti.row_id(i) - _n_equality;
    if (row < 0 || row >= contact_rows.n_rows())
      continue;
    const fem::NormalLaw& law = _interactions[contact_rows.pair[row]].law;
    const double area = law_area(contact_rows, row, law), norm = contact_rows.row_norm[row];
    if (law.kind == fem::NormalLawKind::hard || !(area > 0))
      continue;
    const RowSpring spring = row_spring(law, area, norm, c(i));
    out(i) = 1 / spring.stiffness;
    c(i) += spring.shift;
    if (!std::isfinite(out(i)) || !std::isfinite(c(i)))
      unusable = static_cast<double>(contact_rows.pair[row] + 1);
  }
  // Decided on every rank together, before the QP's collectives.
  unusable = feti.comm().max(unusable);
  FETICON_CHECK(unusable == 0,
                "contact pair " << unusable
                                << ": its law's stiffness at a slave node's overclosure is zero or not "
                                   "finite (a slope, c0 or p0 beyond what the rows can take)");
  return out;
}

bool FetiContactSolve::friction_settled(const std::map<int64_t, double>& normal_before,
                                        const contact::TangentialRows& tangential) const
{
  // Coulomb's fixed point: the bounds mu lambda_N of this QP against those of the next, to the
  // displacement tolerance (relative); Tresca's: the rows in contact, which carry its bound.
  // Each over the rows of the pairs with that law.
  if (!_friction || tangential.n_tangents == 0)
    return true;
  if (normal_before.empty())
    return false; // the QP that starts a run, its bounds on every row
  const auto model_of = [&](int64_t key) { return _interactions[contact::key_pair(key)].friction.model; };
  const auto tresca_only = [&](const std::set<int64_t>& keys) {
    std::set<int64_t> out;
    std::ranges::copy_if(keys, std::inserter(out, out.end()),
                         [&](int64_t key) { return model_of(key) == FrictionModel::tresca; });
    return out;
  };
  if (tresca_only(dual::MultiplierMemory::positive_keys(normal_before, _force_floor)) !=
      tresca_only(_multipliers.active_keys(_force_floor)))
    return false;
  double change = 0, size = 0;
  for (const auto& [key, value] : _multipliers.contact())
  {
    if (model_of(key) != FrictionModel::coulomb)
      continue;
    const auto before = normal_before.find(key);
    const double old_value = before == normal_before.end() ? 0.0 : std::max(before->second, 0.0);
    change += std::pow(std::max(value, 0.0) - old_value, 2);
    size += std::pow(std::max(value, 0.0), 2);
  }
  return std::sqrt(change) <= _convergence.displacement_tolerance * std::sqrt(size);
}

contact::ContactConstraints FetiContactSolve::search_contact(const la::Vector& u_global) const
{
  ScopedTimer t(_timers, "contact search");
  if (_linear_rows)
    return _linear_rows->selected_rows(u_global);
  return pair_rows_at(u_global, _contact_options);
}

void FetiContactSolve::grow_schur_boundary(const la::Vector& u_global, const std::string& where)
{
  // Rows beyond the reach found so far (a sliding or spreading contact): the boundary grows
  // by the reach at u, and the subdomains whose boundary did not change keep their blocks.
  // The reach holds the rows (the same search at u with a wider band than
  // near_contact_fraction). A linear run's rows are among the candidates the boundary was
  // made for: never here.
  const contact::ContactConstraints reach = reach_rows(u_global);
  const std::vector<char> grown = schur_boundary_dofs(_problem, _ever_held, &reach, true);
  for (size_t i = 0; i < grown.size(); ++i)
    _schur_boundary[i] |= grown[i];
  _out.schur_boundary_widened = true;
  ++_out.schur_boundary_growths;
  const int reformed = update_boundary_operators(true);
  log::info(where + "contact rows beyond the Schur boundary: grown to the rows near contact, " +
            std::to_string(reformed) + " subdomains' operators formed again");
}

std::unique_ptr<dual::FetiOperators> FetiContactSolve::coarse_problem(const decomposition::ConstraintRows& rows) const
{
  ScopedTimer t(_timers, "coarse problem");
  auto feti = std::make_unique<dual::FetiOperators>(*_system, rows);
  if (_explicit_operators)
    feti->use_explicit(*_explicit_operators);
  if (_settings.dual.preconditioner == dual::DualPreconditioner::lumped)
    feti->use_lumped_blocks();
  return feti;
}

la::Vector FetiContactSolve::constraint_values(const dual::FetiOperators& feti,
                                               const decomposition::ConstraintRows& rows) const
{
  // c_E = target - B_E u (gluing 0, Dirichlet u_D(t_n)); c_I = current gaps.
  const la::Index m = feti.n_dual();
  la::Vector c = feti.owned(rows.c_vector());
  const la::Vector Bu = feti.apply_B(_u);
  for (la::Index i = 0; i < m && feti.row_id(i) < _n_equality; ++i)
    c(i) -= Bu(i);
  return c;
}

dual::DualPenaltyOptions FetiContactSolve::qp_options(int k)
{
  dual::DualPenaltyOptions dual_options = _settings.dual;
  dual_options.schur = _schur.get();
  dual_options.rtol = qp_rtol(k);
  // rho's least growth at a feasibility stall (smalbe.rho_growth = auto): 3 without friction,
  // where the stall rule's own estimate then sets rho (the leaf pack at 407k DOFs: rho 3, 1 792
  // MPRGP steps, against rho 10 and 3 122 with a least growth of 10); 10 with friction, whose QP
  // stalled at 3 on changefric (docs/contact.md).
  if (dual_options.smalbe_rho_growth == 0)
    dual_options.smalbe_rho_growth = _friction ? 10.0 : 3.0;
  // The QP to the accuracy the outer loop asks in force units (qp.force_rtol): where ||b|| is
  // of the order of the load, rtol ||b|| asked about two decades more than the answer shows
  // (docs/benchmarks.md); where the initial gaps make ||b|| many times the load, rtol ||b|| is
  // the smaller bound and holds.
  if (dual_options.force_rtol > 0 && !_escalated)
    dual_options.force_tolerance = dual_options.force_rtol * force_scale();
  // The rigid-body part of the force residual is G lambda - e, which SMALBE-M's own test
  // (relative to ||b||, dominated by the gaps of inactive contact rows) leaves growing with
  // the dual size: at 326k DOFs the residual stalled at 1-1.5 eps_r. An exact QP therefore
  // also brings the subdomains' net forces (about 2/3 of that residual part) below a quarter
  // of the residual tolerance (a tenth cost more steps where the residual was already low);
  // in a linear run too once the force tolerance can exceed rtol ||b||.
  if (dual_options.rtol <= _settings.dual.rtol && (!_linear || dual_options.force_tolerance > 0))
    dual_options.feasibility_tolerance = 0.25 * _convergence.residual_tolerance * force_scale();
  return dual_options;
}

FetiContactSolve::Correction FetiContactSolve::measure_iteration(const dual::FetiOperators& feti,
                                                                 const dual::DualSolution& solution, OuterIteration& it)
{
  it.qp = solution.report;
  it.final_rho = solution.state.rho;
  it.active_contacts = solution.active_contacts;
  it.feasibility_error = solution.feasibility_error;
  const double du_norm = la::norm(_primal_space, solution.u), u_norm = la::norm(_primal_space, _u);
  const double du_max = _primal_space.max(solution.u.size() > 0 ? solution.u.cwiseAbs().maxCoeff() : 0.0);
  it.displacement_change = du_norm / std::max(u_norm, 1e-300);
  {
    ScopedTimer t(_timers, "internal forces");
    // also the next iteration's, at the same u
    if (std::optional<std::string> inverted = update_internal_force_at_iterate())
      return {du_norm, u_norm, du_max, std::move(inverted)}; // no residual: outer_iteration stops
    const la::Vector r_new = _f_step - _f_int - feti.apply_Bt(solution.state.x);
    it.residual_norm = _decomp->gather_sum(_decomp->gather_stacked(r_new)).norm() / std::max(force_scale(), 1e-300);
  }
  return {du_norm, u_norm, du_max, std::nullopt};
}

bool FetiContactSolve::store_contact_result(const dual::DualSolution& solution,
                                            contact::ContactConstraints contact_rows, const la::Vector& contact_lambda,
                                            const std::string& where)
{
  // A linear run's QP had the rows near contact only; if a left-out candidate is penetrated
  // at its answer, another QP follows with the rows near contact at u (LinearContactRows).
  bool more_rows = false;
  if (_linear_rows)
  {
    const int64_t before = _linear_rows->n_selected();
    more_rows = solution.report.converged && _linear_rows->expand(_decomp->gather_mean(_decomp->gather_stacked(_u)));
    if (more_rows)
      log::info(where + "a contact row left out is penetrated: " + std::to_string(_linear_rows->n_selected() - before) +
                " rows added, " + std::to_string(_linear_rows->n_selected()) + " of " +
                std::to_string(_linear_rows->n_candidates()));
    _out.contact_lambda = _linear_rows->all_multipliers(contact_rows, contact_lambda);
    _out.constraints = _linear_rows->candidates();
  }
  else
  {
    _out.constraints = std::move(contact_rows);
    _out.contact_lambda = contact_lambda;
  }
  return more_rows;
}

/// A linear run solves again for rows it lacked, and for what is left of the round-off of
/// single-precision factors: the dual operator is the inverse of a stiffness perturbed by
/// ~1e-7, and the primal recovery's refinement step against K in double
/// (FetiOperators::apply_K_plus_refined) normally takes the force residual from a few 1e-6 to
/// about 1e-10 (hertz3d at 924k); where a subdomain is so ill-conditioned that one step is not
/// enough, the next QP solves for the correction, as a modified Newton step does. It stops
/// once the residual is below newton.residual_tolerance or no longer falls tenfold an
/// iteration: a linear run's answer never waited for the residual test, and does not start to
/// now (nor, with double factors, iterate for it).
OuterVerdict FetiContactSolve::linear_verdict(bool more_rows, double residual)
{
  const double previous = std::exchange(_previous_residual, residual);
  if (more_rows)
    return OuterVerdict::iterate;
  const bool refine = _settings.factor_precision == la::FactorPrecision::single_precision &&
      residual > _convergence.residual_tolerance && residual < 0.1 * previous;
  return refine ? OuterVerdict::iterate : OuterVerdict::converged;
}

std::string FetiContactSolve::floor_message(const OuterIteration& it, double du_max, double feasibility_error) const
{
  char floor[400];
  std::snprintf(floor, sizeof floor,
                "residual %.2e > newton.residual_tolerance %.2e with a round-off correction (|du|_inf %.1e m <= "
                "1e-9 L) and the same contact set, so another iteration repeats this one; the residual left is "
                "the dual QP's equilibrium error (its feasibility %.1e at qp.rtol %.0e): a smaller qp.rtol or a "
                "larger residual_tolerance",
                it.residual_norm, _convergence.residual_tolerance, du_max, feasibility_error, _settings.dual.rtol);
  return floor;
}

void FetiContactSolve::end_load_step(const LoadStep& record)
{
  if (_diverged)
    return; // u is not finite: the solution keeps the last converged step's
  const la::Vector u_stacked_global = _decomp->gather_stacked(_u);
  _out.u = _decomp->gather_mean(u_stacked_global);
  _out.temperature_change = _temperature_change;
  if (!record.converged && record.floor.empty())
    return;
  if (!_out.plastic.empty())
  {
    // The increment is accepted: its J2 states become the ones the next starts from.
    _system->commit_plastic_state(_u);
    _system->plastic_states(_out.plastic);
    // f_int from the committed states (equal to the trial one's to round-off), as a restart
    // computes it: the continued run is then bitwise the uninterrupted one.
    update_internal_force();
    // Every rank's outputs (the .frd, .dat and checkpoint of rank 0 among them) read every cell's.
    if (!_decomp->comm().serial())
      _out.plastic.unpack(_decomp->comm().all_gather(_out.plastic.pack(_out.owned_cells)));
  }
  RestartState& r = _out.restart;
  r.escalated = _escalated;
  if (!_out.plastic.empty())
  {
    std::vector<int32_t> cells(static_cast<size_t>(_problem.mesh.n_cells()));
    std::iota(cells.begin(), cells.end(), 0);
    r.plastic = _out.plastic.pack(cells);
  }
  r.completed_steps = _step;
  const la::Vector start = _history.start_values(_history.point(_step).stage);
  r.stage_start.assign(start.data(), start.data() + start.size());
  r.linear_rows_selected = _linear_rows ? _linear_rows->selected_indices() : std::vector<int32_t>{};
  r.schur_boundary.clear();
  if (_out.schur_boundary_widened)
    for (size_t i = 0; i < _schur_boundary.size(); ++i)
      if (_schur_boundary[i])
        r.schur_boundary.push_back(static_cast<int32_t>(i));
  r.u_stacked = u_stacked_global;
  r.dual = _multipliers.state();
  r.dual.x = _equality_by_id;
  r.contact_slave.clear();
  r.contact_pair.clear();
  r.contact_lambda.clear();
  r.contact_tangential.clear();
  const auto& tangential = _multipliers.tangential();
  for (const auto& [key, value] : _multipliers.contact())
  {
    r.contact_slave.push_back(contact::key_node(key));
    r.contact_pair.push_back(contact::key_pair(key));
    r.contact_lambda.push_back(value);
    if (!tangential.empty())
    {
      const auto t = tangential.find(key);
      r.contact_tangential.push_back(t == tangential.end() ? 0.0 : t->second[0]);
      r.contact_tangential.push_back(t == tangential.end() ? 0.0 : t->second[1]);
    }
  }
}
} // namespace

double explicit_forming_bytes(std::vector<double> boundary_sizes, int threads)
{
  // Arrays of |b_s|^2 doubles held beside the kept blocks while one subdomain is formed, the
  // partial factor of K_s among them (its size grows as |b_s|^2 does in 3D): fitted to the
  // peaks of hertz3d at 97k DOFs with explicit operators, 1 rank on 2 threads and 2 ranks on
  // one thread each (docs/benchmarks.md, "The memory guard's estimate").
  constexpr double arrays = 3;
  std::sort(boundary_sizes.begin(), boundary_sizes.end(), std::greater<>());
  double bytes = 0;
  for (size_t k = 0; k < boundary_sizes.size() && k < static_cast<size_t>(std::max(1, threads)); ++k)
    bytes += arrays * sizeof(double) * boundary_sizes[k] * boundary_sizes[k];
  return bytes;
}

ContactSolution solve_feti_contact(const fem::Problem& problem, const SolverSettings& settings, TimerTable& timers,
                                   const StepCallback& on_step, const ContactSolution* previous, par::Communicator comm)
{
  problem.validate();
  const auto run_start = std::chrono::steady_clock::now();
  ContactSolution out;
  FetiContactSolve solve(problem, settings, timers, comm, out);
  const int first_step = previous ? solve.restore(*previous) : 1;
  run_load_steps(solve, solve.history(), first_step, settings.max_outer_iterations, settings.max_cutbacks, out,
                 on_step);
  if (out.completed)
    timers.add("total solve", seconds_since(run_start));
  return out;
}
} // namespace feticon::nonlinear
