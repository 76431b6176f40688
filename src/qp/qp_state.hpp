#pragma once
/// @file Where a QP solve ended, and so where the solve of a nearby QP starts: the unknown,
/// SMALBE-M's multiplier of Cx = 0 with its M and rho, and the scale of the operator. The same
/// type is SMALBE-M's start, the dual solve's warm start, what the outer loop keeps between
/// its QPs and what a checkpoint stores (app/checkpoint.cpp); each layer holds it in its own
/// coordinates (for FETI: omega in the scaled G~ rows inside SMALBE-M, as a coarse vector by
/// rigid modes outside it; dual::ContactQp maps between them). The active set is not stored:
/// it follows from x and the bounds.

#include "la/types.hpp"

namespace feticon::qp
{
struct QpState
{
  la::Vector x;             ///< the unknown (multipliers); empty: start from 0
  la::Vector omega;         ///< SMALBE-M: the multiplier of Cx = 0; empty: 0
  double M = 0;             ///< SMALBE-M's M; 0: the options' M0
  double rho = 0;           ///< SMALBE-M's rho; 0 (or below the options' rho): the options' rho
  double operator_norm = 0; ///< ||A|| of a solve with the same operator; 0: estimated
};
} // namespace feticon::qp
