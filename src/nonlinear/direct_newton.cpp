#include "nonlinear/direct_newton.hpp"

#include "common/error.hpp"
#include "common/parallel.hpp"
#include "common/log.hpp"
#include "la/cholmod.hpp"

#include <sstream>

namespace feticon::nonlinear
{
DirectNewtonReport solve_direct_newton(const fem::Assembler& assembler, const fem::ConstrainedDofs& constrained,
                                       const la::Vector& f_ext, la::Vector& u, const DirectNewtonOptions& options)
{
  FETICON_CHECK(options.load_steps >= 1, "load_steps must be >= 1");
  const fem::LoadHistory history(constrained.dofs, {{f_ext, constrained.values, options.load_steps}});
  return solve_direct_newton(assembler, history, u, options);
}

DirectNewtonReport solve_direct_newton(const fem::Assembler& assembler, const fem::LoadHistory& history, la::Vector& u,
                                       const DirectNewtonOptions& options)
{
  // One undecomposed factorization: BLAS is the parallelism (common/parallel.hpp).
  const ScopedBlasThreads blas(threads());
  const int64_t n = assembler.domain().n_dofs();
  FETICON_CHECK(history.terms().front().force.size() == n && u.size() == n,
                "direct Newton: vector sizes do not match the mesh (" << n << " DOFs)");
  const bool linear = assembler.kinematics() == fem::Kinematics::linear;
  DirectNewtonReport report;
  for (int step = 1; step <= history.n_steps(); ++step)
  {
    const fem::ConstrainedDofs target = history.prescribed(step);
    const fem::ConstraintElimination elimination(n, target, options.equations);
    const la::Vector f = history.external_force(step);
    const double f_norm = std::max(elimination.reduce_force(f).norm(), 1e-300);
    // Impose this step's prescribed values (and the equations' dependent DOFs) first; then
    // every correction is zero there.
    elimination.impose(u);
    fem::ConstrainedDofs homogeneous = target;
    homogeneous.values.setZero();
    const fem::ConstraintElimination correction(n, homogeneous, options.equations);

    int iteration = 0;
    bool converged = false;
    while (iteration < options.max_iterations && !converged)
    {
      la::SparseMatrix K;
      la::Vector f_int;
      assembler.assemble(u, fem::StiffnessKind::tangent, &K, &f_int);
      const la::Vector r = f - f_int;
      const double r_norm = correction.reduce_force(r).norm() / f_norm;
      la::CholmodFactor factor;
      factor.factorize(correction.reduce_matrix(K), "the tangent stiffness (direct Newton)");
      const la::Vector du = correction.expand(factor.solve(correction.reduce_force(r)));
      FETICON_CHECK(du.allFinite(), "direct Newton produced a non-finite correction");
      u += du;
      ++iteration;
      const double du_rel = du.norm() / std::max(u.norm(), 1e-300);
      std::ostringstream line;
      line << "  direct Newton step " << step << " iteration " << iteration << ": residual " << r_norm << ", |du|/|u| "
           << du_rel;
      log::iteration(line.str());
      report.residual_norm = r_norm;
      converged = linear || du_rel <= options.rtol;
    }
    report.iterations.push_back(iteration);
    if (!converged)
      return report;
  }
  report.converged = true;
  return report;
}
} // namespace feticon::nonlinear
