#include "nonlinear/direct_newton.hpp"

#include "common/error.hpp"
#include "common/parallel.hpp"
#include "common/log.hpp"
#include "la/cholmod.hpp"

#include <sstream>

namespace feticon::nonlinear
{
DirectNewtonReport solve_direct_newton(const fem::Assembler& assembler,
                                       const fem::ConstrainedDofs& constrained,
                                       const la::Vector& f_ext, la::Vector& u,
                                       const DirectNewtonOptions& options)
{
  // One undecomposed factorization: BLAS is the parallelism (common/parallel.hpp).
  const ScopedBlasThreads blas(threads());
  const int64_t n = assembler.domain().n_dofs();
  FETICON_CHECK(f_ext.size() == n && u.size() == n, "direct Newton: vector sizes do not match "
                                                    "the mesh (" << n << " DOFs)");
  FETICON_CHECK(options.load_steps >= 1, "load_steps must be >= 1");
  const bool linear = assembler.kinematics() == fem::Kinematics::linear;
  DirectNewtonReport report;
  for (int step = 1; step <= options.load_steps; ++step)
  {
    const double t = static_cast<double>(step) / options.load_steps;
    fem::ConstrainedDofs target = constrained;
    target.values *= t;
    const fem::DirichletElimination elimination(n, target);
    const la::Vector f = t * f_ext;
    const double f_norm = std::max(elimination.restrict(f).norm(), 1e-300);
    // Impose this step's prescribed values first; then every correction is zero there.
    for (size_t i = 0; i < target.dofs.size(); ++i)
      u(target.dofs[i]) = target.values(static_cast<la::Index>(i));
    fem::ConstrainedDofs homogeneous = target;
    homogeneous.values.setZero();
    const fem::DirichletElimination correction(n, homogeneous);

    int iteration = 0;
    bool converged = false;
    while (iteration < options.max_iterations && !converged)
    {
      la::SparseMatrix K;
      la::Vector f_int;
      assembler.assemble(u, fem::StiffnessKind::tangent, &K, &f_int);
      const la::Vector r = f - f_int;
      const double r_norm = correction.restrict(r).norm() / f_norm;
      la::CholmodFactor factor;
      factor.factorize(correction.reduce_matrix(K), "the tangent stiffness (direct Newton)");
      const la::Vector du = correction.expand(factor.solve(correction.restrict(r)));
      FETICON_CHECK(du.allFinite(), "direct Newton produced a non-finite correction");
      u += du;
      ++iteration;
      const double du_rel = du.norm() / std::max(u.norm(), 1e-300);
      std::ostringstream line;
      line << "  direct Newton step " << step << " iteration " << iteration << ": residual "
           << r_norm << ", |du|/|u| " << du_rel;
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
