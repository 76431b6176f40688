#include "dual/primal_recovery.hpp"

#include "common/error.hpp"

namespace feticon::dual
{
PrimalSolution recover_primal(const FetiOperators& feti, const la::Vector& f, const la::Vector& c,
                              const la::Vector& lambda, const std::vector<char>& active)
{
  const la::Vector K_plus_r = feti.apply_K_plus(f - feti.apply_Bt(lambda));
  // F lambda - d = B K+ (B' lambda - f) + c = c - B K+ (f - B' lambda).
  la::Vector residual = c - feti.apply_B(K_plus_r);
  for (la::Index i = 0; i < residual.size(); ++i)
    if (!active[i])
      residual(i) = 0;
  const la::SparseMatrix G_A = feti.G_columns(active);
  PrimalSolution out;
  if (feti.n_kernel() > 0)
  {
    Eigen::LLT<la::Matrix> llt(la::Matrix(G_A * G_A.transpose()));
    FETICON_CHECK(llt.info() == Eigen::Success,
                  "primal recovery: the active constraints do not fix every rigid-body motion");
    out.alpha = llt.solve(la::Vector(G_A * residual));
  }
  else
    out.alpha.resize(0);
  out.u = K_plus_r + feti.apply_R(out.alpha);
  return out;
}
} // namespace feticon::dual
