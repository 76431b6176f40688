#include "nonlinear/feti_contact_solver.hpp"

#include "common/error.hpp"
#include "common/log.hpp"
#include "decomposition/constraint_rows.hpp"
#include "decomposition/explicit_boundary_operators.hpp"
#include "decomposition/subdomain_operators.hpp"
#include "dual/dual_penalty_problem.hpp"
#include "nonlinear/outer_convergence.hpp"
#include "la/vector_space.hpp"
#include "par/block_space.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <set>
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
  return decomposition::partition_structured(problem.mesh,
                                             {std::max(1, s.subdomains / problem.mesh.n_bodies()), 1, 1});
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

/// The multipliers of rows id_begin <= id < id_end, replicated on every rank (0 for ids that
/// have no row); small: used for contact rows and for checkpoints.
la::Vector rows_by_id(const dual::FetiOperators& feti, const la::Vector& lambda, int64_t id_begin,
                      int64_t id_end)
{
  std::vector<int64_t> ids;
  std::vector<double> values;
  for (la::Index i = 0; i < feti.n_dual(); ++i)
    if (feti.row_id(i) >= id_begin && feti.row_id(i) < id_end)
    {
      ids.push_back(feti.row_id(i));
      values.push_back(lambda(i));
    }
  const std::vector<int64_t> all_ids = feti.comm().all_gather(ids);
  const std::vector<double> all_values = feti.comm().all_gather(values);
  la::Vector out = la::Vector::Zero(id_end - id_begin);
  for (size_t k = 0; k < all_ids.size(); ++k)
    out(all_ids[k] - id_begin) = all_values[k];
  return out;
}

/// Nodes whose DOFs are on the boundary of the Dirichlet preconditioner's Schur complements
/// besides the subdomain interfaces: supported nodes and the nodes of both contact surfaces
/// (decomposition/schur_complements.hpp).
std::vector<char> schur_boundary_nodes(const fem::Problem& problem, const fem::ConstrainedDofs& dirichlet)
{
  std::vector<char> boundary(problem.mesh.n_nodes(), 0);
  for (int64_t dof : dirichlet.dofs)
    if (!problem.eliminated[dof % 3]) // plane strain's u_z = 0 is no row
      boundary[dof / 3] = 1;
  for (const auto& pair : problem.contacts)
    for (const std::string& set : {pair.slave, pair.master})
      for (int32_t node : problem.mesh.face_set_nodes(set))
        boundary[node] = 1;
  return boundary;
}

/// dual.operator = auto: explicit when the dense blocks fit a quarter of the available
/// memory (and 4 GiB per rank) and forming them costs less than they save over the steps
/// the run is expected to take. Costs in flops of the factor substitutions: an implicit step
/// applies K_s+ and the K_ii solve of S_s once each, about 4 (nnz(L_s) + nnz(L_ii)) ~
/// 8 nnz(L_s); an explicit one two dense products of 2 |b_s|^2, which run at 3 times the
/// flop rate of the substitutions; forming the blocks is |b_s| such substitution pairs, which
/// the multi-column solves in blocks of 32 do in a quarter of the time. Measured with the
/// products by BLAS dsymv: Hertz, 19k DOFs, 8 subdomains, |b_s| ~ 320: a dual product
/// 2.5 ms implicit, 0.32 ms explicit (model: 4.6x); sphere on block, 17k DOFs, 4 subdomains,
/// |b_s| ~ 1 560: 9.2 ms against 3.4 ms (model 2.8x; the blocks, 75 MiB, stream from memory
/// at every step). Expected steps: 100 per load step, 5 times as many with large
/// displacements (docs/benchmarks.md).
std::pair<bool, std::string> choose_explicit(const SolverSettings& settings, const decomposition::SubdomainSystem& system,
                                             const decomposition::SchurComplements* schur, const par::Communicator& comm)
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
  const auto& decomp = system.decomposition();
  double setup = 0, implicit_step = 0, explicit_step = 0;
  for (int32_t s = decomp.first_owned(); s < decomp.end_owned(); ++s)
  {
    const double nb = static_cast<double>(schur->boundary(s).size());
    const double substitution = 8.0 * static_cast<double>(system.operators(s).K_plus.factor_nonzeros());
    setup += 0.25 * nb * substitution;
    implicit_step += substitution;
    explicit_step += 4 * nb * nb / 3;
  }
  const int64_t bytes = comm.sum(decomposition::explicit_operator_bytes(system, *schur));
  const double budget = std::min(0.25 * static_cast<double>(available_memory_bytes()), 4.0 * (1L << 30)) * comm.size();
  const double steps = 100.0 * settings.steps() * (settings.kinematics == fem::Kinematics::linear ? 1 : 5);
  setup = static_cast<double>(comm.sum(static_cast<int64_t>(setup)));
  implicit_step = static_cast<double>(comm.sum(static_cast<int64_t>(implicit_step)));
  explicit_step = static_cast<double>(comm.sum(static_cast<int64_t>(explicit_step)));
  char reason[256];
  if (static_cast<double>(bytes) > budget)
  {
    std::snprintf(reason, sizeof reason, "auto: the dense blocks (%.2g GiB) exceed the memory budget (%.2g GiB)",
                  static_cast<double>(bytes) / (1L << 30), budget / (1L << 30));
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

/// Slave nodes whose contact multiplier is positive, with the dual solver's threshold against
/// round-off (1e-12 of the largest).
std::set<int32_t> active_slave_nodes(const std::map<int32_t, double>& contact_lambda)
{
  double largest = 0;
  for (const auto& [node, value] : contact_lambda)
    largest = std::max(largest, value);
  std::set<int32_t> active;
  for (const auto& [node, value] : contact_lambda)
    if (value > 1e-12 * largest)
      active.insert(node);
  return active;
}

std::string format_iteration(const OuterIteration& it)
{
  char line[256];
  std::snprintf(line, sizeof line,
                "step %2d  outer %2d  inner %5d  residual %9.2e  |du|/|u| %9.2e  active %5ld  %7.2f s",
                it.load_step, it.iteration, it.qp.iterations, it.residual_norm,
                it.displacement_change, static_cast<long>(it.active_contacts), it.seconds);
  return line;
}
} // namespace

ContactSolution solve_feti_contact(const fem::Problem& problem, const SolverSettings& settings,
                                   TimerTable& timers, const StepCallback& on_step,
                                   const ContactSolution* previous, par::Communicator comm)
{
  problem.validate();
  FETICON_CHECK(problem.contacts.size() == 1, "the FETI contact solver handles exactly one contact "
                                              "pair; the problem has " << problem.contacts.size());
  const auto run_start = std::chrono::steady_clock::now();
  ContactSolution out;

  std::unique_ptr<decomposition::Decomposition> decomp;
  {
    ScopedTimer t(timers, "decomposition");
    decomp = std::make_unique<decomposition::Decomposition>(
        problem.mesh, make_partition(problem, settings), problem.eliminated, comm);
  }
  const par::BlockSpace primal_space = owned_subdomain_space(*decomp);
  out.n_subdomains = decomp->n_subdomains();
  if (!comm.serial())
  {
    for (int32_t s = decomp->first_owned(); s < decomp->end_owned(); ++s)
    {
      const auto& cells = decomp->subdomain(s).domain.cells;
      out.owned_cells.insert(out.owned_cells.end(), cells.begin(), cells.end());
    }
    std::sort(out.owned_cells.begin(), out.owned_cells.end());
  }
  decomposition::SubdomainSystem system(*decomp, problem.materials, settings.kinematics,
                                        settings.generalized_inverse);
  la::Vector u = la::Vector::Zero(decomp->n_primal());
  const fem::ConstrainedDofs dirichlet = problem.all_constrained_dofs();
  const bool use_schur = settings.dual.preconditioner == dual::DualPreconditioner::dirichlet;
  const std::vector<char> schur_boundary = use_schur ? schur_boundary_nodes(problem, dirichlet) : std::vector<char>();
  std::unique_ptr<decomposition::SchurComplements> schur;
  std::unique_ptr<decomposition::ExplicitBoundaryOperators> explicit_operators;
  auto update_stiffness = [&]
  {
    system.update(u, &timers);
    if (use_schur)
    {
      ScopedTimer t(timers, "preconditioner setup"); // K_ii factorizations
      schur = std::make_unique<decomposition::SchurComplements>(system, schur_boundary);
    }
    const auto [use_explicit, reason] = choose_explicit(settings, system, schur.get(), comm);
    out.dual_operator = use_explicit ? "explicit" : "implicit";
    out.dual_operator_reason = reason;
    log::info("dual operators: " + out.dual_operator + " (" + reason + ")");
    explicit_operators.reset();
    if (use_explicit)
    {
      ScopedTimer t(timers, "explicit operators");
      explicit_operators = std::make_unique<decomposition::ExplicitBoundaryOperators>(system, *schur);
      out.explicit_operator_bytes = comm.sum(explicit_operators->bytes());
    }
  };
  update_stiffness(); // K_0 and R(X), kept for the whole run (modified Newton)
  const la::Vector f_ext = problem.external_force();
  const la::Vector f_ext_stacked = decomp->scatter_split(f_ext);
  const double f_norm = f_ext.norm();
  const Eigen::Vector3d extent = problem.mesh.nodes.colwise().maxCoeff() - problem.mesh.nodes.colwise().minCoeff();
  const OuterConvergence convergence{settings.displacement_tolerance, settings.residual_tolerance, extent.norm()};
  const contact::ContactPair pair{problem.contacts[0].slave, problem.contacts[0].master};
  contact::ContactOptions contact_options;
  contact_options.search_distance = settings.search_distance;
  contact_options.formulation = settings.formulation;

  la::Vector lambda_previous;  ///< owned multipliers of the last solve (equality rows first)
  /// SMALBE-M's state after the last solve: without its equality multiplier the next QP
  /// starts with the full gradient of the bound multipliers' coarse part and rebuilds it
  /// over ~10 outer iterations (Hertz, large displacements: 787 -> 345 MPRGP steps).
  dual::DualWarmStart warm_smalbe;
  la::Vector restart_lambda;   ///< equality multipliers by row id, from a checkpoint
  std::map<int32_t, double> previous_contact; ///< contact multiplier by slave node
  std::set<int32_t> previous_active;          ///< slave nodes of the active rows, last iteration
  const bool linear = settings.kinematics == fem::Kinematics::linear;
  int first_step = 1;
  if (previous)
  {
    const RestartState& r = previous->restart;
    FETICON_CHECK(r.u_stacked.size() == decomp->n_primal_global(),
                  "restart: the checkpoint has " << r.u_stacked.size() << " unknowns, this problem "
                                                 << decomp->n_primal_global() << " (different mesh or subdomains?)");
    FETICON_CHECK(r.completed_steps < settings.steps(),
                  "restart: all " << settings.steps() << " load steps are already done");
    u = decomp->owned_slice(r.u_stacked);
    restart_lambda = r.lambda;
    warm_smalbe = {{}, r.smalbe_coarse_multiplier, r.smalbe_M, r.smalbe_rho, r.pfp_norm};
    for (size_t i = 0; i < r.contact_slave.size(); ++i)
      previous_contact[r.contact_slave[i]] = r.contact_lambda[i];
    previous_active = active_slave_nodes(previous_contact);
    out.history = previous->history;
    out.steps = previous->steps;
    // A refreshed K_M(u) is rebuilt at the first outer iteration of the step, as it would
    // have been in the uninterrupted run.
    first_step = r.completed_steps + 1;
  }
  // Internal force at the current u, kept up to date after every update.
  la::Vector f_int;
  {
    ScopedTimer t(timers, "internal forces");
    f_int = system.internal_force(u);
  }
  for (int step = first_step; step <= settings.steps(); ++step)
  {
    const double t_n = static_cast<double>(step) / settings.steps();
    fem::ConstrainedDofs target = dirichlet;
    target.values *= t_n;
    const auto equality = decomposition::build_equality_rows(*decomp, target);
    const int64_t n_equality = equality.n_global();
    LoadStep record;
    record.load_factor = t_n;
    la::Vector equality_by_id; ///< for the checkpoint of a converged step
    bool forcing = !linear && settings.forcing > 0;
    for (int k = 1; k <= settings.max_outer_iterations; ++k)
    {
      const auto iteration_start = std::chrono::steady_clock::now();
      const bool refresh = !linear && ((settings.stiffness == StiffnessUpdate::load_step && k == 1 && step > 1) ||
                                       (settings.stiffness == StiffnessUpdate::iteration && (step > 1 || k > 1)));
      if (refresh)
      {
        update_stiffness(); // K_M(u) and R(X + u)
        warm_smalbe.pfp_norm = 0; // a new F: estimate ||PFP|| again
      }
      const la::Vector u_global = decomp->gather_mean(decomp->gather_stacked(u));
      contact::ContactConstraints contact_rows;
      la::Vector residual;
      {
        ScopedTimer t(timers, "contact search");
        contact_rows = contact::build_contact_constraints(problem.mesh, u_global, pair, contact_options);
      }
      residual = t_n * f_ext_stacked - f_int;
      decomposition::ConstraintRows rows = equality.rows;
      rows.append(decomposition::rows_from_global(*decomp, contact_rows.B, contact_rows.c), n_equality);

      std::unique_ptr<dual::FetiOperators> feti;
      {
        ScopedTimer t(timers, "coarse problem");
        feti = std::make_unique<dual::FetiOperators>(system, rows);
        if (explicit_operators)
          feti->use_explicit(*explicit_operators);
      }
      // c_E = target - B_E u (gluing 0, Dirichlet t_n u_D); c_I = current gaps.
      const la::Index m = feti->n_dual();
      la::Vector c = feti->owned(rows.c_vector());
      const la::Vector Bu = feti->apply_B(u);
      for (la::Index i = 0; i < m && feti->row_id(i) < n_equality; ++i)
        c(i) -= Bu(i);
      // Warm start: equality rows keep their ids and owners (owned ones come first, in the
      // same order); contact rows are matched by slave node (rows are rebuilt every
      // iteration), new rows start at 0. SMALBE-M's multiplier is a coarse vector, indexed by
      // the subdomains' rigid modes, whose numbering does not change.
      dual::DualWarmStart warm = warm_smalbe;
      if (lambda_previous.size() > 0 || restart_lambda.size() > 0)
      {
        warm.lambda = la::Vector::Zero(m);
        for (la::Index i = 0; i < m; ++i)
        {
          const int64_t id = feti->row_id(i);
          if (id < n_equality)
            warm.lambda(i) = restart_lambda.size() > 0 ? restart_lambda(id) : lambda_previous(i);
          else if (const auto it = previous_contact.find(contact_rows.slave_node[id - n_equality]);
                   it != previous_contact.end())
            warm.lambda(i) = it->second;
        }
        restart_lambda.resize(0);
      }
      // Inexact QPs while the outer iteration contracts (SolverSettings::forcing); once a
      // correction grows, the QP errors are being amplified: exact QPs for the rest of the step.
      if (k > 2 && out.history.back().displacement_change >= out.history.rbegin()[1].displacement_change)
        forcing = false;
      dual::DualPenaltyOptions dual_options = settings.dual;
      dual_options.schur = schur.get();
      if (forcing)
      {
        const double forced = k == 1 ? settings.max_forcing_rtol
                                     : std::min(settings.max_forcing_rtol,
                                                settings.forcing * out.history.back().displacement_change);
        dual_options.rtol = std::max(settings.dual.rtol, forced);
      }
      dual::DualSolution solution;
      {
        ScopedTimer t(timers, "dual solve (MPRGP)");
        solution = dual::solve_contact_dual(*feti, c, residual, n_equality, dual_options, warm);
      }
      u += solution.u;
      lambda_previous = solution.lambda;
      warm_smalbe = {{}, solution.coarse_multiplier, solution.smalbe_M, solution.smalbe_rho, solution.pfp_norm};
      const la::Vector contact_lambda =
          rows_by_id(*feti, solution.lambda, n_equality, n_equality + contact_rows.n_rows());
      previous_contact.clear();
      for (size_t i = 0; i < contact_rows.slave_node.size(); ++i)
        previous_contact[contact_rows.slave_node[i]] = contact_lambda(static_cast<la::Index>(i));
      std::set<int32_t> active = active_slave_nodes(previous_contact);

      OuterIteration it;
      it.load_step = step;
      it.iteration = k;
      it.qp = solution.report;
      it.final_rho = solution.smalbe_rho;
      it.active_contacts = solution.active_contacts;
      it.feasibility_error = solution.feasibility_error;
      const double du_norm = la::norm(primal_space, solution.u), u_norm = la::norm(primal_space, u);
      const double du_max = primal_space.max(solution.u.size() > 0 ? solution.u.cwiseAbs().maxCoeff() : 0.0);
      it.displacement_change = du_norm / std::max(u_norm, 1e-300);
      {
        ScopedTimer t(timers, "internal forces");
        f_int = system.internal_force(u); // also the next iteration's, at the same u
        const la::Vector r_new = t_n * f_ext_stacked - f_int - feti->apply_Bt(solution.lambda);
        const double force_scale =
            std::max(t_n * f_norm, decomp->gather_sum(decomp->gather_stacked(f_int)).norm());
        it.residual_norm = decomp->gather_sum(decomp->gather_stacked(r_new)).norm() / std::max(force_scale, 1e-300);
      }
      // A diverging outer loop shows as a non-finite residual before anything else fails; the
      // iteration is no result, so it stays out of the history (no NaN in history.csv).
      if (!std::isfinite(it.residual_norm) || !std::isfinite(it.displacement_change))
      {
        out.reason = "load step " + std::to_string(step) + ", outer iteration " + std::to_string(k) +
                     ": the outer loop diverged (non-finite residual): use more load_steps or "
                     "newton.stiffness=iteration";
        out.steps.push_back(record);
        return out;
      }
      it.seconds = seconds_since(iteration_start);
      out.history.push_back(it);
      record.inner_iterations.push_back(it.qp.iterations);
      log::info(format_iteration(it));

      out.constraints = std::move(contact_rows);
      out.contact_lambda = contact_lambda;
      out.n_dual = feti->n_dual_global();
      out.n_kernel = feti->n_kernel();
      out.feasibility_error = solution.feasibility_error;
      if (!solution.report.converged)
      {
        out.u = decomp->gather_mean(decomp->gather_stacked(u));
        out.reason = "load step " + std::to_string(step) + ", outer iteration " +
                     std::to_string(k) + ": " + solution.report.reason;
        out.steps.push_back(record);
        return out;
      }
      record.outer_iterations = k;
      record.displacement_change = it.displacement_change;
      record.residual_norm = it.residual_norm;
      // The multipliers are the answer (pressures), and an inexact QP leaves them off by far
      // more than its tolerance suggests (that is relative to ||b||, which the gaps of the
      // inactive rows dominate: Hertz at refinement 1 stopped after a QP at rtol 1e-7 had a
      // peak pressure 14 % high). So a step ends only after a QP solved to qp.rtol; if the
      // test passes after a forced one, the next QP, warm-started at the answer, is exact.
      const bool exact_qp = dual_options.rtol <= settings.dual.rtol;
      const bool converged =
          linear || convergence.converged(du_norm, u_norm, du_max, it.residual_norm, active, previous_active);
      previous_active = std::move(active);
      if (converged && !exact_qp)
        forcing = false;
      else if (converged)
      {
        record.converged = true;
        equality_by_id = rows_by_id(*feti, solution.lambda, 0, n_equality);
        break;
      }
    }
    out.steps.push_back(record);
    const la::Vector u_stacked_global = decomp->gather_stacked(u);
    out.u = decomp->gather_mean(u_stacked_global);
    if (!record.converged)
    {
      out.reason = "load step " + std::to_string(step) + " did not converge in " +
                   std::to_string(settings.max_outer_iterations) + " outer iterations (|du|/|u| = " +
                   std::to_string(record.displacement_change) + ")";
      return out;
    }
    out.restart.completed_steps = step;
    out.restart.u_stacked = u_stacked_global;
    out.restart.lambda = equality_by_id;
    out.restart.smalbe_coarse_multiplier = warm_smalbe.coarse_multiplier;
    out.restart.smalbe_M = warm_smalbe.M;
    out.restart.smalbe_rho = warm_smalbe.rho;
    out.restart.pfp_norm = warm_smalbe.pfp_norm;
    out.restart.contact_slave.clear();
    out.restart.contact_lambda.clear();
    for (const auto& [node, value] : previous_contact)
    {
      out.restart.contact_slave.push_back(node);
      out.restart.contact_lambda.push_back(value);
    }
    if (on_step)
      on_step(step, out);
  }
  out.converged = true;
  timers.add("total solve", seconds_since(run_start));
  return out;
}
} // namespace feticon::nonlinear
