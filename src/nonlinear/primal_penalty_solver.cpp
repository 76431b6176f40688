#include "nonlinear/primal_penalty_solver.hpp"

#include "common/error.hpp"
#include "common/parallel.hpp"
#include "fem/assembler.hpp"
#include "fem/constraint_elimination.hpp"
#include "la/cholmod.hpp"
#include "nonlinear/contact_penalty.hpp"
#include "nonlinear/load_stepping.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>

namespace feticon::nonlinear
{
namespace
{
/// The phases of the primal penalty solve (run_load_steps drives them): one undecomposed
/// penalized system per outer iteration, the active set made consistent inside it.
class PrimalPenaltySolve final : public LoadStepPhases
{
public:
  PrimalPenaltySolve(const fem::Problem& problem, const SolverSettings& settings, TimerTable& timers,
                     ContactSolution& out);

  void begin_load_step(int step, double t) override;
  IterationOutcome outer_iteration(int k, OuterIteration& it) override;
  void end_load_step(const LoadStep&) override { _out.u = _u; }
  std::string format(const OuterIteration& it) const override;
  bool cut_back(int step) override;
  fem::LoadHistory& history() { return _history; }

private:
  /// Small displacements: the penalized system for the total u.
  void solve_linear(const contact::ContactConstraints& rows, const la::Vector& eps, OuterIteration& it);
  /// Large: the linearized step du at the current configuration.
  void solve_increment(const contact::ContactConstraints& rows, const la::Vector& eps, const la::Vector& f_int,
                       OuterIteration& it);

  const fem::Problem& _problem;
  const SolverSettings& _settings;
  TimerTable& _timers;
  ContactSolution& _out;
  const bool _linear;
  const int64_t _n;
  fem::Assembler _assembler;
  fem::LoadHistory _history; ///< split where a load step is cut back
  contact::ContactPair _pair;
  contact::ContactOptions _contact_options;
  la::Vector _u;
  la::Vector _u_step_start; ///< u at the start of the load step (a cutback's)
  la::SparseMatrix _K;
  la::SparseMatrix _K_pen;
  la::Vector _f_pen;

  int _step = 0;
  la::Vector _f_step;           ///< f(t_n) of the load history
  fem::ConstrainedDofs _target; ///< the supports' values at this load step
  std::vector<char> _active;    ///< penalized rows
};

PrimalPenaltySolve::PrimalPenaltySolve(const fem::Problem& problem, const SolverSettings& settings, TimerTable& timers,
                                       ContactSolution& out)
    : _problem(problem), _settings(settings), _timers(timers), _out(out),
      _linear(settings.kinematics == fem::Kinematics::linear), _n(3 * static_cast<int64_t>(problem.mesh.n_nodes())),
      _assembler(problem.mesh, fem::whole_mesh_domain(problem.mesh), problem.materials, settings.kinematics),
      _history(settings.load_history(problem)), _pair{problem.contacts[0].slave, problem.contacts[0].master,
                                                      problem.contacts[0].slave_nodes},
      _u(la::Vector::Zero(_n))
{
  _contact_options.search_distance = settings.search_distance;
  _contact_options.formulation = settings.interaction(problem.contacts[0]).formulation;
  _out.n_subdomains = 1;
  if (_linear)
  {
    ScopedTimer t(timers, "assembly");
    _K = _assembler.stiffness(_u, fem::StiffnessKind::tangent);
    _out.penalty = settings.eps_n_factor * _K.diagonal().maxCoeff();
  }
}

std::string PrimalPenaltySolve::format(const OuterIteration& it) const
{
  char line[200];
  std::snprintf(line, sizeof line, "step %2d  penalty iteration %2d  active %5ld  |du|/|u| %9.2e  %7.2f s",
                it.load_step, it.iteration, static_cast<long>(it.active_contacts), it.displacement_change, it.seconds);
  return line;
}

void PrimalPenaltySolve::begin_load_step(int step, double)
{
  _step = step;
  _f_step = _history.external_force(step);
  _history.start_stage(step, _u); // a DOF held from this step on ramps from its displacement
  _target = _history.prescribed(step);
  _active.clear();
  _u_step_start = _u;
}

bool PrimalPenaltySolve::cut_back(int step)
{
  if (_linear)
    return false;
  _u = _u_step_start;
  _history.split(step);
  return true;
}

IterationOutcome PrimalPenaltySolve::outer_iteration(int k, OuterIteration& it)
{
  contact::ContactConstraints rows;
  {
    ScopedTimer t(_timers, "contact search");
    // Small displacements: contact in the reference configuration, total u unknown.
    // Large: rows in the current configuration, c = current gap, du unknown.
    rows =
        contact::build_contact_constraints(_problem.mesh, _linear ? la::Vector::Zero(_n) : _u, _pair, _contact_options);
  }
  // contact.law = deck with a linear law: its springs K A_i |b_i|^2 (contact_penalty.hpp), pressed
  // from the overclosure sigma_inf / K on (fem::NormalLaw), which the solve takes as a shifted c.
  const fem::NormalLaw& law = _settings.interaction(_problem.contacts[0]).law;
  const bool own_law = law.kind == fem::NormalLawKind::linear;
  la::Vector law_stiffness, shift = la::Vector::Zero(rows.c.size());
  if (own_law)
    law_springs(rows, law, law_stiffness, shift);
  rows.c += shift;
  // Active set: violated rows (linear: v = B u - c at the current u; TL: current gap < 0).
  // The very first solve also takes touching rows (g = 0), or a body held only by
  // contact would have no spring at all.
  const la::Vector violation = _linear ? la::Vector(rows.B * _u - rows.c) : la::Vector(-rows.c);
  std::vector<char> new_active(rows.c.size());
  for (la::Index i = 0; i < rows.c.size(); ++i)
    new_active[i] = (_step == 1 && k == 1) ? violation(i) >= 0 : violation(i) > 0;
  if (_linear && k > 1 && new_active == _active)
    return IterationOutcome::step_converged(false); // the last solve's active set is consistent
  _active = new_active;

  la::Vector f_int;
  if (!_linear)
  {
    ScopedTimer t(_timers, "assembly");
    _assembler.assemble(_u, fem::StiffnessKind::tangent, &_K, &f_int);
    if (_out.penalty == 0)
      _out.penalty = _settings.eps_n_factor * _K.diagonal().maxCoeff();
  }
  const la::Vector eps = own_law ? law_stiffness : row_penalties(rows, _out.penalty);
  penalty_terms(rows, _active, eps, _K_pen, _f_pen);
  {
    ScopedTimer t(_timers, "factorization + solve");
    if (_linear)
      solve_linear(rows, eps, it);
    else
      solve_increment(rows, eps, f_int, it);
  }
  FETICON_CHECK(_u.allFinite(), "primal penalty: the solution is not finite");
  rows.c -= shift; // the gaps of the outputs
  _out.constraints = std::move(rows);
  it.qp.iterations = 1;
  it.active_contacts = std::count(_active.begin(), _active.end(), 1);
  if (!_linear && it.displacement_change <= _settings.displacement_tolerance)
    return IterationOutcome::step_converged();
  return IterationOutcome::next();
}

void PrimalPenaltySolve::solve_linear(const contact::ContactConstraints& rows, const la::Vector& eps,
                                      OuterIteration& it)
{
  la::CholmodFactor factor;
  const la::SparseMatrix A = _K + _K_pen;
  // Supports and linear equations are eliminated exactly; the penalty is contact's alone
  // (fem/constraint_elimination.hpp).
  const fem::ConstraintElimination elim(_n, _target, _problem.all_equations(), &_problem.mesh);
  factor.factorize(elim.reduce_matrix(A), "the penalized stiffness");
  const la::Vector u_new = elim.expand(factor.solve(elim.reduce_rhs(A, _f_step + _f_pen)));
  it.displacement_change = (u_new - _u).norm() / std::max(u_new.norm(), 1e-300);
  _u = u_new;
  _out.contact_lambda = eps.cwiseProduct(rows.B * _u - rows.c).cwiseMax(0.0);
}

void PrimalPenaltySolve::solve_increment(const contact::ContactConstraints& rows, const la::Vector& eps,
                                         const la::Vector& f_int, OuterIteration& it)
{
  // This step's supports (and the linear equations' dependent DOFs) first; then every
  // correction is zero there.
  fem::ConstraintElimination(_n, _target, _problem.all_equations(), &_problem.mesh).impose(_u);
  fem::ConstrainedDofs homogeneous = _target;
  homogeneous.values.setZero();
  const fem::ConstraintElimination elim(_n, homogeneous, _problem.all_equations(), &_problem.mesh);
  // Active set of the linearized step made consistent first (rows violated after the
  // step, B du - c > 0), as in the linear case: taking it from the current gaps alone
  // lets nodes at the contact edge flip at every Newton iteration.
  la::CholmodFactor factor;
  la::Vector du;
  for (int inner = 0; inner < 30; ++inner)
  {
    factor.factorize(elim.reduce_matrix(_K + _K_pen), "the penalized tangent stiffness");
    du = elim.expand(factor.solve(elim.reduce_force(_f_step - f_int + _f_pen)));
    const la::Vector predicted = rows.B * du - rows.c;
    std::vector<char> consistent(rows.c.size());
    for (la::Index i = 0; i < predicted.size(); ++i)
      consistent[i] = predicted(i) > 0;
    if (consistent == _active || std::count(consistent.begin(), consistent.end(), 1) == 0)
      break;
    _active = consistent;
    penalty_terms(rows, _active, eps, _K_pen, _f_pen);
  }
  _u += du;
  it.displacement_change = du.norm() / std::max(_u.norm(), 1e-300);
  _out.contact_lambda = eps.cwiseProduct(rows.B * du - rows.c).cwiseMax(0.0);
}
} // namespace

ContactSolution solve_primal_penalty(const fem::Problem& problem, const SolverSettings& settings, TimerTable& timers,
                                     const StepCallback& on_step)
{
  // One undecomposed factorization: BLAS is the parallelism (common/parallel.hpp).
  const ScopedBlasThreads blas(threads());
  problem.validate();
  FETICON_CHECK(problem.contacts.size() == 1,
                "method = primal_penalty handles one contact pair, the problem has "
                    << problem.contacts.size() << ": use method smalbe or dual_penalty");
  const fem::NormalLawKind law = settings.interaction(problem.contacts[0]).law.kind;
  FETICON_CHECK(law == fem::NormalLawKind::hard || law == fem::NormalLawKind::linear,
                "the contact pair's " << fem::normal_law_name(law)
                                      << " pressure-overclosure law is not solved by feticon (contact.law=deck solves "
                                         "linear laws; contact.law=hard solves the pair as hard contact)");
  FETICON_CHECK(!settings.has_friction(problem),
                "the contact pair has friction, which method = primal_penalty does "
                "not model: use method smalbe or dual_penalty");
  FETICON_CHECK(std::ranges::none_of(problem.steps, [](const fem::Step& s) { return !s.changed_law.empty(); }),
                "a step changes the contact law (*CHANGE SURFACE BEHAVIOR), which method = primal_penalty does not "
                "model: use method smalbe or dual_penalty");
  FETICON_CHECK(std::ranges::none_of(problem.steps, [](const fem::Step& s) { return !s.removed_contacts.empty(); }),
                "a step removes the contact pair (*MODEL CHANGE), which method = primal_penalty does not model: use "
                "method smalbe or dual_penalty");
  FETICON_CHECK(!problem.has_temperatures(),
                "the problem has temperatures, which method = primal_penalty does not "
                "model: use method smalbe or dual_penalty");
  FETICON_CHECK(!problem.has_plastic_body(),
                "a body is plastic, which method = primal_penalty does not model: use "
                "method smalbe or dual_penalty");
  FETICON_CHECK(problem.frames.empty(),
                "supports act along local axes (*TRANSFORM), which method = primal_penalty does not model: use "
                "method smalbe or dual_penalty");
  const auto run_start = std::chrono::steady_clock::now();
  ContactSolution out;
  PrimalPenaltySolve solve(problem, settings, timers, out);
  run_load_steps(solve, solve.history(), 1, settings.max_outer_iterations, settings.max_cutbacks, out, on_step);
  if (out.completed)
    timers.add("total solve", seconds_since(run_start));
  return out;
}
} // namespace feticon::nonlinear
