#include "fem/material.hpp"

#include "common/error.hpp"

#include <cmath>

namespace feticon::fem
{
Eigen::Matrix<double, 6, 6> Material::elasticity_matrix() const
{
  const double lambda = lame_lambda(), mu = lame_mu();
  Eigen::Matrix<double, 6, 6> D = Eigen::Matrix<double, 6, 6>::Zero();
  D.topLeftCorner<3, 3>().setConstant(lambda);
  D.topLeftCorner<3, 3>().diagonal().array() += 2 * mu;
  D.bottomRightCorner<3, 3>().diagonal().setConstant(mu);
  return D;
}

void Material::set_hyperelastic(const Hyperelastic& law)
{
  hyperelastic = law;
  young = law.initial_young();
  poisson = law.initial_poisson();
}

void Material::check(const std::string& where) const
{
  FETICON_CHECK(std::isfinite(young) && young > 0, where << ": Young's modulus E = " << young << " must be positive");
  FETICON_CHECK(std::isfinite(poisson) && poisson > -1 && poisson < 0.5,
                where << ": Poisson's ratio nu = " << poisson << " must lie in (-1, 0.5)");
  FETICON_CHECK(std::isfinite(density) && density >= 0,
                where << ": the density rho = " << density << " must be finite and not negative");
  // Negative alpha is physical (zirconium tungstate, some composites' fibre direction).
  FETICON_CHECK(std::isfinite(expansion),
                where << ": the expansion coefficient alpha = " << expansion << " is not finite");
  if (is_hyperelastic())
  {
    hyperelastic.check(where);
    FETICON_CHECK(!is_plastic(), where << ": plasticity of a hyperelastic material is not implemented");
    FETICON_CHECK(expansion == 0, where << ": thermal expansion of a hyperelastic material is not implemented");
  }
  if (!is_plastic())
    return;
  plastic.check(where);
  for (size_t k = 0; k + 1 < plastic.stress.size(); ++k)
    FETICON_CHECK(plastic.hardening(plastic.plastic_strain[k]) > -3 * lame_mu(),
                  where << ": the plastic table softens faster than 3 G = " << 3 * lame_mu() << " Pa between points "
                        << k + 1 << " and " << k + 2 << ": the radial return has no solution");
}
} // namespace feticon::fem
