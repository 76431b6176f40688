#pragma once
/// @file The hardening of a J2 (von Mises) material: the yield stress in uniaxial loading as a
/// function of the equivalent plastic strain, piecewise linear through the points of a
/// `*PLASTIC` table (CalculiX's and Abaqus's definition: von Mises stress, equivalent plastic
/// strain; the first point at zero plastic strain is the initial yield stress; beyond the last
/// point the yield stress stays constant). Isotropic hardening grows the yield surface by the
/// table; kinematic hardening (HARDENING=KINEMATIC) keeps its radius at the first stress and
/// moves its centre, the back stress, by the table's rise (CalculiX's incplas_lin.f).

#include <string>
#include <vector>

namespace feticon::fem
{
struct YieldCurve
{
  std::vector<double> stress;         ///< sigma_y at each point (Pa), from the initial yield stress
  std::vector<double> plastic_strain; ///< the equivalent plastic strain of each point, 0 first, increasing
  bool kinematic = false;             ///< kinematic hardening (the file comment), else isotropic

  bool empty() const { return stress.empty(); }
  /// sigma_y at equivalent plastic strain `eqps` >= 0.
  double yield_stress(double eqps) const;
  /// d sigma_y / d eqps on the segment that holds `eqps` (the one after it at a point;
  /// 0 beyond the last point).
  double hardening(double eqps) const;
  /// The index of the segment [plastic_strain[k], plastic_strain[k+1]) holding `eqps`; the
  /// last point's index beyond it.
  size_t segment(double eqps) const;
  /// Throws feticon::Error naming `where` unless the table starts at zero plastic strain, its
  /// strains increase, and every stress is positive and finite.
  void check(const std::string& where) const;
};
} // namespace feticon::fem
