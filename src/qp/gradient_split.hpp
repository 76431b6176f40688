#pragma once
/// @file What MPRGP and MPGP reduce in one pass over a feasible x with gradient g = Ax - b:
/// the squared norms of the free gradient phi and the chopped gradient beta, the product
/// phi~'phi of the reduced free gradient with phi, and the cost f(x) = 1/2 x'(g - b).

#include "la/types.hpp"
#include "la/vector_space.hpp"

namespace feticon::qp
{
struct GradientSplit
{
  double free_norm2 = 0.0;            ///< ||phi||^2
  double chopped_norm2 = 0.0;         ///< ||beta||^2
  double reduced_free_dot_free = 0.0; ///< phi~'phi
  double cost = 0.0;                  ///< 1/2 x'(g - b)
};

/// f(x) = 1/2 x'(g - b) for g = Ax - b, without a product with A; summed over the ranks.
double quadratic_cost(const la::VectorSpace& space, const la::Vector& x, const la::Vector& g, const la::Vector& b);
} // namespace feticon::qp
