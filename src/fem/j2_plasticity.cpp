#include "fem/j2_plasticity.hpp"

#include "common/error.hpp"

#include <cmath>

namespace feticon::fem
{
namespace
{
/// s : s of a deviator in Voigt form with plain shears.
double contract(const Voigt& s) { return s.head<3>().squaredNorm() + 2 * s.tail<3>().squaredNorm(); }

Voigt deviator(const Voigt& sigma)
{
  Voigt s = sigma;
  s.head<3>().array() -= sigma.head<3>().mean();
  return s;
}

struct Trial
{
  Voigt stress, deviator; ///< the deviator relative to the back stress
  double q = 0;           ///< von Mises stress of that deviator
};

Trial trial_state(const Material& material, const Voigt& strain, double thermal_stress,
                  const PlasticPointState& committed)
{
  Trial t;
  t.stress = material.elasticity_matrix() * (strain - committed.plastic_strain);
  t.stress.head<3>().array() -= thermal_stress;
  t.deviator = deviator(t.stress) - committed.back_stress;
  t.q = std::sqrt(1.5 * contract(t.deviator));
  return t;
}

/// The consistent tangent of a yielded point: trial state t, increment d from eqps d_0 + d.
Eigen::Matrix<double, 6, 6> consistent_tangent(const Material& material, const Trial& t, double d, double eqps)
{
  const double G = material.lame_mu();
  const double bulk = material.young / (3 * (1 - 2 * material.poisson));
  const double theta = 1 - 3 * G * d / t.q;
  const double theta_bar = 1 / (1 + material.plastic.hardening(eqps) / (3 * G)) - (1 - theta);
  const Voigt n = t.deviator / std::sqrt(contract(t.deviator));
  // 2 G theta I_dev on engineering shears: 2 G theta (delta_ij - 1/3) on the normals, G theta
  // on each shear; n : eps = n_v . eps_v with n_v's plain shears.
  Eigen::Matrix<double, 6, 6> C = Eigen::Matrix<double, 6, 6>::Zero();
  C.topLeftCorner<3, 3>().setConstant(bulk - 2 * G * theta / 3);
  C.topLeftCorner<3, 3>().diagonal().array() += 2 * G * theta;
  C.bottomRightCorner<3, 3>().diagonal().setConstant(G * theta);
  C -= 2 * G * theta_bar * n * n.transpose();
  return C;
}
} // namespace

double plastic_increment(const YieldCurve& curve, double shear_modulus, double q_trial, double eqps, double scale)
{
  // On one segment k the equation is linear: d = (q_tr - s sigma_k - s H_k (eqps - p_k)) / (3 G + s H_k).
  const size_t last = curve.stress.size() - 1;
  for (size_t k = curve.segment(eqps);; ++k)
  {
    const double hardening = k < last
        ? scale * (curve.stress[k + 1] - curve.stress[k]) / (curve.plastic_strain[k + 1] - curve.plastic_strain[k])
        : 0.0;
    const double denominator = 3 * shear_modulus + hardening;
    FETICON_CHECK(denominator > 0,
                  "the plastic table softens faster than 3 G = " << 3 * shear_modulus << " Pa (slope " << hardening
                                                                 << " Pa): the radial return has no solution");
    const double d = (q_trial - scale * curve.stress[k] - hardening * (eqps - curve.plastic_strain[k])) / denominator;
    if (k == last || eqps + d < curve.plastic_strain[k + 1])
      return d;
  }
}

J2Update j2_return(const Material& material, const Voigt& strain, double thermal_stress,
                   const PlasticPointState& committed, Eigen::Matrix<double, 6, 6>* tangent)
{
  const Trial t = trial_state(material, strain, thermal_stress, committed);
  J2Update out{t.stress, committed, false};
  const double eqps = committed.equivalent_plastic_strain;
  // A point that ended the last increment on the yield surface starts the next one there: its
  // trial stress at the increment's start exceeds sigma_y by round-off alone. Taken as yielding,
  // its tangent is the elasto-plastic one for a step that may unload (a release diverged from
  // it: the block's tangent H, 200 times softer than E); within 1e-10 of sigma_y the point is
  // elastic (a stress error below 1e-10 sigma_y).
  const YieldCurve& curve = material.plastic;
  const double radius = curve.kinematic ? curve.stress.front() : curve.yield_stress(eqps);
  if (t.q <= radius * (1 + 1e-10))
  {
    if (tangent)
      *tangent = material.elasticity_matrix();
    return out;
  }
  const double G = material.lame_mu();
  // Kinematic: the table's rise from eqps moves the centre, the radius stays (file comment).
  const double shift = curve.kinematic ? curve.yield_stress(eqps) - radius : 0.0;
  const double d = plastic_increment(curve, G, t.q + shift, eqps);
  out.plastic = true;
  if (curve.kinematic)
    out.state.back_stress += (curve.yield_stress(eqps + d) - curve.yield_stress(eqps)) / t.q * t.deviator;
  out.stress = t.stress - (3 * G * d / t.q) * t.deviator;
  // deps_p = 3/2 d s_tr / q_tr as a tensor; engineering shears double its shear entries.
  Voigt direction = 1.5 / t.q * t.deviator;
  direction.tail<3>() *= 2;
  out.state.plastic_strain += d * direction;
  out.state.equivalent_plastic_strain = eqps + d;
  if (tangent)
    *tangent = consistent_tangent(material, t, d, eqps + d);
  return out;
}
} // namespace feticon::fem
