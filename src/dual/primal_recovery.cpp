#include "dual/primal_recovery.hpp"

#include "common/error.hpp"
#include "dual/projector.hpp"

#include <optional>

namespace feticon::dual
{
namespace
{
/// A pivot ratio of G_A G_A' below this leaves a mode to the sliding rows (file comment).
constexpr double weakly_held = 1e-4;

/// The rows that hold with equality: y on the active rows and, on each sliding disc, its
/// component across the slide (p p' y); 0 elsewhere.
la::Vector held_part(const la::Vector& y, const std::vector<char>& active, const SlidingRows& sliding)
{
  la::Vector out = y;
  for (la::Index i = 0; i < out.size(); ++i)
    if (!active[i])
      out(i) = 0;
  for (const SlidingDisc& d : sliding.discs)
  {
    const double across = d.p_i * y(d.i) + d.p_j * y(d.j);
    out(d.i) = d.p_i * across;
    out(d.j) = d.p_j * across;
  }
  return out;
}

/// The sliding rows: y on the boxes at a bound and, on each sliding disc, its component along
/// the slide; 0 elsewhere.
la::Vector slide_part(const la::Vector& y, const SlidingRows& sliding)
{
  la::Vector out = la::Vector::Zero(y.size());
  for (const la::Index i : sliding.boxes)
    out(i) = y(i);
  for (const SlidingDisc& d : sliding.discs)
  {
    const double along = d.p_j * y(d.i) - d.p_i * y(d.j); // t = (p_j, -p_i)
    out(d.i) = d.p_j * along;
    out(d.j) = -d.p_i * along;
  }
  return out;
}

/// alpha of the file comment where the active rows leave rigid modes free: G H G' and G S G'
/// (H the held rows, S the sliding ones) formed column by column, one G' and two G products
/// per rigid mode; alpha holds the held rows in the least-squares sense and, in the modes they
/// leave free, gives the least slip. Empty where the sliding rows leave a mode free too.
std::optional<la::Vector> sliding_coarse_solve(const FetiOperators& feti, const la::Vector& residual,
                                               const std::vector<char>& active, const SlidingRows& sliding)
{
  const la::Index n = feti.n_kernel();
  la::Matrix M_held(n, n), M_slide(n, n);
  for (la::Index k = 0; k < n; ++k)
  {
    const la::Vector Gt_k = feti.apply_Gt(la::Vector::Unit(n, k));
    M_held.col(k) = feti.apply_G(held_part(Gt_k, active, sliding));
    M_slide.col(k) = feti.apply_G(slide_part(Gt_k, sliding));
  }
  const Eigen::SelfAdjointEigenSolver<la::Matrix> held(0.5 * (M_held + M_held.transpose()));
  const la::Vector& values = held.eigenvalues();
  const double cut = weakly_held * weakly_held * std::max(values(n - 1), 0.0);
  la::Index n_free = 0;
  while (n_free < n && values(n_free) <= cut)
    ++n_free;
  const la::Matrix& V = held.eigenvectors();
  const la::Matrix range = V.rightCols(n - n_free);
  la::Vector alpha = range *
      ((range.transpose() * feti.apply_G(held_part(residual, active, sliding))).cwiseQuotient(values.tail(n - n_free)));
  if (n_free == 0)
    return alpha;
  // The free modes N: beta minimizes |(H + S)(G' (alpha + N beta) - residual)|, where H holds
  // them weakly at most.
  const la::Matrix N = V.leftCols(n_free);
  const la::Matrix M = 0.5 * (M_held + M_held.transpose() + M_slide + M_slide.transpose());
  const Eigen::SelfAdjointEigenSolver<la::Matrix> slide(la::Matrix(N.transpose() * M * N));
  if (!(slide.eigenvalues()(0) > 1e-12 * std::max(M.diagonal().maxCoeff(), 0.0)))
    return std::nullopt;
  const la::Vector b =
      N.transpose() * (feti.apply_G(held_part(residual, active, sliding) + slide_part(residual, sliding)) - M * alpha);
  alpha += N * (slide.eigenvectors() * (slide.eigenvectors().transpose() * b).cwiseQuotient(slide.eigenvalues()));
  return alpha;
}
} // namespace

PrimalSolution recover_primal(const FetiOperators& feti, const la::Vector& f, const la::Vector& c,
                              const la::Vector& lambda, const std::vector<char>& active, const std::string& unheld,
                              const SlidingRows& sliding)
{
  const la::Vector K_plus_r = feti.apply_K_plus_refined(f - feti.apply_Bt(lambda));
  // F lambda - d = B K+ (B' lambda - f) + c = c - B K+ (f - B' lambda).
  const la::Vector residual = c - feti.apply_B(K_plus_r);
  PrimalSolution out;
  if (feti.n_kernel() > 0)
  {
    const std::string free_mode = !unheld.empty()
        ? unheld
        : "no active contact holds a body that only contact can hold (the active constraints leave a rigid-body "
          "motion free): is the load zero, too small to press the bodies together, or pulling them apart? Check "
          "loads and the contact pairs";
    const CoarseProjector active_coarse(feti, std::nothrow, active);
    // Rows at their bound can leave a mode held only by the small tilt of deformed normals: G_A
    // G_A' then passes the rank test but alpha is huge (friction2's block, 4e6 times its
    // displacement): the sliding rows decide such modes too.
    const bool any_sliding = feti.comm().max(sliding.empty() ? 0.0 : 1.0) > 0; // a collective
    if (active_coarse.pivot_ratio() < weakly_held && any_sliding)
    {
      std::optional<la::Vector> alpha = sliding_coarse_solve(feti, residual, active, sliding);
      FETICON_CHECK(alpha, free_mode);
      out.alpha = std::move(*alpha);
    }
    else
    {
      FETICON_CHECK(active_coarse.full_rank(), free_mode);
      out.alpha = active_coarse.coarse_solve(feti.apply_G(held_part(residual, active, {}), &active));
    }
  }
  else
    out.alpha.resize(0);
  out.u = K_plus_r + feti.apply_R(out.alpha);
  return out;
}
} // namespace feticon::dual
