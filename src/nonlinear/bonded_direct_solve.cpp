#include "nonlinear/bonded_direct_solve.hpp"

#include "common/error.hpp"
#include "common/parallel.hpp"
#include "common/timer.hpp"
#include "fem/assembler.hpp"
#include "fem/constraint_elimination.hpp"
#include "la/cholmod.hpp"
#include "nonlinear/contact_penalty.hpp"

#include <algorithm>
#include <chrono>

namespace feticon::nonlinear
{
std::vector<int32_t> active_slave_nodes(const ContactSolution& solution)
{
  std::vector<int32_t> nodes;
  for (la::Index i = 0; i < solution.contact_lambda.size(); ++i)
    if (solution.contact_lambda(i) > 0)
      nodes.push_back(solution.constraints.slave_node[i]);
  return nodes;
}

BondedSolve bonded_direct_solve(const fem::Problem& problem, const SolverSettings& settings,
                                const std::vector<int32_t>& bonded_nodes)
{
  // One undecomposed factorization: BLAS is the parallelism (common/parallel.hpp).
  const ScopedBlasThreads blas(threads());
  problem.validate();
  FETICON_CHECK(problem.contacts.size() == 1, "the bonded direct solve handles one contact pair");
  BondedSolve out;
  const int64_t n = 3 * static_cast<int64_t>(problem.mesh.n_nodes());
  auto start = std::chrono::steady_clock::now();
  const fem::Assembler assembler(problem.mesh, fem::whole_mesh_domain(problem.mesh), problem.materials,
                                 fem::Kinematics::linear);
  const la::Vector zero = la::Vector::Zero(n);
  const la::SparseMatrix K = assembler.stiffness(zero, fem::StiffnessKind::tangent);
  out.penalty = settings.eps_n_factor * K.diagonal().maxCoeff();

  contact::ContactOptions options;
  options.search_distance = settings.search_distance;
  options.formulation = settings.formulation;
  out.constraints = contact::build_contact_constraints(
      problem.mesh, zero, {problem.contacts[0].slave, problem.contacts[0].master, problem.contacts[0].slave_nodes},
      options);
  const auto& rows = out.constraints;
  // Rows are sorted by slave node, one row per node.
  std::vector<char> bonded(rows.c.size(), 0);
  for (int32_t node : bonded_nodes)
  {
    const auto it = std::lower_bound(rows.slave_node.begin(), rows.slave_node.end(), node);
    FETICON_CHECK(it != rows.slave_node.end() && *it == node,
                  "bonded direct solve: slave node " << node << " has no contact row at u = 0 (not a "
                                                     << "slave node, or farther than the search distance)");
    bonded[it - rows.slave_node.begin()] = 1;
  }
  out.n_bonded = std::count(bonded.begin(), bonded.end(), 1);
  const la::Vector eps = row_penalties(rows, out.penalty);
  la::SparseMatrix K_pen;
  la::Vector f_pen;
  penalty_terms(rows, bonded, eps, K_pen, f_pen);
  const la::SparseMatrix A = K + K_pen;
  const fem::ConstraintElimination elimination(n, problem.all_constrained_dofs(), problem.equations, &problem.mesh);
  const la::SparseMatrix A_free = elimination.reduce_matrix(A);
  const la::Vector rhs_free = elimination.reduce_rhs(A, problem.external_force() + f_pen);
  out.assembly_seconds = seconds_since(start);

  start = std::chrono::steady_clock::now();
  la::CholmodFactor factor;
  factor.factorize(A_free, "the bonded stiffness (is every body supported once the bonded nodes are tied?)");
  out.factorization_seconds = seconds_since(start);
  out.factor_nonzeros = factor.factor_nonzeros();

  start = std::chrono::steady_clock::now();
  const la::Vector u_free = factor.solve(rhs_free);
  out.u = elimination.expand(u_free);
  out.solve_seconds = seconds_since(start);
  // CHOLMOD factorizes a singular stiffness (a body held only by contact, none of its nodes
  // bonded) without complaint when round-off keeps the pivots positive; the residual shows it.
  const double residual = (A_free * u_free - rhs_free).norm() / std::max(rhs_free.norm(), 1e-300);
  FETICON_CHECK(out.u.allFinite() && residual <= 1e-8,
                "bonded direct solve: the bonded system is singular (relative residual "
                    << residual << "): bond at least one node of every body held only by contact");

  out.contact_lambda = eps.cwiseProduct(rows.B * out.u - rows.c);
  for (la::Index i = 0; i < out.contact_lambda.size(); ++i)
    if (!bonded[i])
      out.contact_lambda(i) = 0;
  return out;
}
} // namespace feticon::nonlinear
