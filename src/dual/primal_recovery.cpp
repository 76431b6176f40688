#include "dual/primal_recovery.hpp"

#include "common/error.hpp"
#include "dual/projector.hpp"

namespace feticon::dual
{
PrimalSolution recover_primal(const FetiOperators& feti, const la::Vector& f, const la::Vector& c,
                              const la::Vector& lambda, const std::vector<char>& active, const std::string& unheld)
{
  const la::Vector K_plus_r = feti.apply_K_plus_refined(f - feti.apply_Bt(lambda));
  // F lambda - d = B K+ (B' lambda - f) + c = c - B K+ (f - B' lambda).
  la::Vector residual = c - feti.apply_B(K_plus_r);
  for (la::Index i = 0; i < residual.size(); ++i)
    if (!active[i])
      residual(i) = 0;
  PrimalSolution out;
  if (feti.n_kernel() > 0)
  {
    const CoarseProjector active_coarse(feti, std::nothrow, active);
    FETICON_CHECK(active_coarse.full_rank() || unheld.empty(), unheld);
    FETICON_CHECK(active_coarse.full_rank(),
                  "no active contact holds a body that only contact can hold (the active constraints leave a "
                  "rigid-body motion free): is the load zero, too small to press the bodies together, or "
                  "pulling them apart? Check loads and the contact pairs");
    out.alpha = active_coarse.coarse_solve(feti.apply_G(residual, &active));
  }
  else
    out.alpha.resize(0);
  out.u = K_plus_r + feti.apply_R(out.alpha);
  return out;
}
} // namespace feticon::dual
