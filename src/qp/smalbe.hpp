#pragma once
/// @file SMALBE-M: semimonotonic augmented Lagrangian for bound and equality constraints
/// with adaptive M (Dostál 2006, 2009; ALGORITHMS.md section 1).
///
/// Solves   min 1/2 x'Hx - b'x   subject to   x >= l,  C x = 0,
/// where C has orthonormal rows (C C' = I) and H already contains the augmentation
/// rho C'C (for FETI: H = PFP + rho Q with Q = G~'G~, C = G~). Outer loop:
///   x <- MPRGP on (H, b - C'omega, l), warm-started, stopped when
///        ||g_P|| <= min(M ||Cx||, eta)   or the final test holds;
///   final test: ||g_P|| <= rtol ||b|| and ||Cx|| <= rtol ||b||;
///   omega <- omega + rho C x;
///   M <- M / beta if L(x, omega) did not increase by at least rho/2 ||Cx||^2.
/// Usage:
///   qp::Smalbe smalbe(H, C, {.rho = 1});
///   const qp::SmalbeReport r = smalbe.solve(b, lower, x);

#include "qp/mprgp.hpp"

namespace feticon::qp
{
/// An operator with orthonormal rows: x -> C x (m rows) and y -> C' y.
class EqualityOperator
{
public:
  virtual ~EqualityOperator() = default;
  virtual la::Vector apply(const la::Vector& x) const = 0;
  virtual la::Vector apply_transpose(const la::Vector& y) const = 0;
};

struct SmalbeOptions
{
  double rtol = 1e-6;        ///< final test on ||g_P|| and ||Cx||, relative to ||b||
  double rho = 1.0;          ///< the augmentation in H (multiplier update step)
  double M0 = 1.0;           ///< initial M (in units where ||H|| ~ max(1, rho))
  double beta = 2.0;         ///< M <- M / beta when L does not increase enough
  double eta_factor = 0.1;   ///< eta = eta_factor ||b||
  int max_outer_iterations = 200;
  int max_inner_iterations = 100000; ///< total MPRGP steps over all outer iterations
  MprgpOptions mprgp{};      ///< gamma, alpha_bar, monitor; its rtol and stop are set here
};

struct SmalbeReport : QpReport
{
  int outer_iterations = 0;
  double equality_residual = 0; ///< ||Cx|| / ||b|| at the end
  double final_M = 0;
  la::Vector omega;             ///< multiplier of Cx = 0
};

class Smalbe
{
public:
  Smalbe(const la::LinearOperator& H, const EqualityOperator& C, SmalbeOptions options);
  /// @param[in,out] x initial guess on input (projected onto x >= l), solution on output
  SmalbeReport solve(const la::Vector& b, const la::Vector& lower, la::Vector& x);

private:
  const la::LinearOperator& _H;
  const EqualityOperator& _C;
  SmalbeOptions _options;
};
} // namespace feticon::qp
