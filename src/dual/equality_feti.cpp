#include "dual/equality_feti.hpp"

#include "dual/primal_recovery.hpp"
#include "dual/projector.hpp"
#include "common/error.hpp"

#include <optional>

namespace feticon::dual
{
FetiSolution solve_equality_feti(const FetiOperators& feti, const la::Vector& c, const la::Vector& f_stacked,
                                 const qp::CgOptions& options, FetiPreconditioner preconditioner,
                                 const decomposition::SchurComplements* schur)
{
  const CoarseProjector projector(feti);
  const la::Vector e = feti.apply_Rt(f_stacked);
  const la::Vector lambda_tilde = projector.particular_solution(e);
  const la::Vector d = feti.apply_B(feti.apply_K_plus(f_stacked)) - c;
  const la::Vector b = projector.apply_P(d - feti.apply_F(lambda_tilde));

  const FOperator F(feti);
  const ProjectedOperator PFP(F, projector, 0.0);
  const ProjectorP P(projector, feti.n_dual());
  la::Vector mu = la::Vector::Zero(feti.n_dual());
  FetiSolution out;
  const LumpedPreconditioner lumped(feti);
  qp::CgOptions cg = options;
  if (preconditioner == FetiPreconditioner::lumped)
    cg.preconditioner = &lumped;
  std::optional<DirichletPreconditioner> dirichlet;
  if (preconditioner == FetiPreconditioner::dirichlet)
  {
    FETICON_CHECK(schur, "the Dirichlet preconditioner needs the subdomain Schur complements");
    cg.preconditioner = &dirichlet.emplace(feti, *schur);
  }
  out.report = qp::conjugate_gradient(PFP, b, mu, cg, &P);
  out.lambda = lambda_tilde + mu;
  const std::vector<char> all_rows(feti.n_dual(), 1);
  PrimalSolution primal = recover_primal(feti, f_stacked, c, out.lambda, all_rows);
  out.u = std::move(primal.u);
  out.alpha = std::move(primal.alpha);
  return out;
}
} // namespace feticon::dual
