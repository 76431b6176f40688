#pragma once
/// @file The multipliers of the last dual solve, kept by what identifies a row from one outer
/// iteration to the next, to warm-start the next solve (the dual problem changes only in its
/// contact rows and right-hand side):
///  - equality rows by their id: ids and owners do not change, and a rank's owned rows come
///    first, in the same order;
///  - contact rows by their key (pair, slave node), contact::contact_key: the rows are rebuilt
///    at every outer iteration, and a key without a row last time starts at 0;
///  - SMALBE-M's state and the ||PFP|| estimate (qp::QpState, as DualSolution::state): its
///    multiplier of G lambda = e is a coarse vector indexed by the subdomains' rigid modes,
///    whose numbering does not change.

#include "dual/dual_penalty_problem.hpp"
#include "dual/feti_operators.hpp"

#include <array>
#include <cstdint>
#include <map>
#include <set>
#include <vector>

namespace feticon::dual
{
class MultiplierMemory
{
public:
  /// The start of the solve with the operators `feti`, whose rows with ids [0, n_equality) are
  /// the equality rows, id n_equality + j the contact row of key contact_key[j] (contact::contact_key), and,
  /// with friction (n_tangents > 0), id n_equality + n_contact + n_tangents j + k its tangent k.
  qp::QpState warm_start(const FetiOperators& feti, int64_t n_equality, const std::vector<int64_t>& contact_key,
                         int n_tangents = 0) const;

  /// Keeps the multipliers of `solution` (of the solve warm_start was asked for) and returns
  /// its normal contact multipliers by row, replicated on every rank; with friction also the
  /// tangential ones in `tangential` (n_tangents per contact row).
  la::Vector remember(const FetiOperators& feti, const DualSolution& solution, int64_t n_equality,
                      const std::vector<int64_t>& contact_key, int n_tangents = 0, la::Vector* tangential = nullptr);

  /// The equality rows changed (a step holds other DOFs): the next solve starts their
  /// multipliers at 0 (those of a checkpoint included).
  void forget_equality()
  {
    _equality_forgotten = true;
    _restart_equality.resize(0);
  }

  /// F changed (a refreshed stiffness): ||PFP|| must be estimated again.
  void forget_operator_norm() { _state.operator_norm = 0; }

  /// The state of a checkpoint: `state` with x the equality multipliers by row id (used by the
  /// next solve only), the contact multipliers by key and, with friction, two
  /// tangential multipliers per key (`tangential` empty: none).
  void restore(qp::QpState state, const std::vector<int64_t>& contact_key, const std::vector<double>& contact_lambda,
               const std::vector<double>& tangential = {});

  /// Contact multiplier by key (pair, slave node), of the last solve.
  const std::map<int64_t, double>& contact() const { return _contact; }
  /// Tangential multipliers by key (the second 0 in plane strain), of the last solve.
  const std::map<int64_t, std::array<double, 2>>& tangential() const { return _tangential; }
  /// The state of the last solve, without its multipliers (SMALBE-M's omega, M, rho; ||PFP||).
  const qp::QpState& state() const { return _state; }
  /// Keys whose contact multiplier is positive, with the dual solver's threshold
  /// against round-off (1e-12 of the largest) and above `floor` (a force at round-off: when
  /// nothing is loaded, the largest multiplier is itself noise).
  std::set<int64_t> active_keys(double floor = 0) const { return positive_keys(_contact, floor); }

  /// The keys of `contact` (multiplier by key) that active_keys would call active.
  static std::set<int64_t> positive_keys(const std::map<int64_t, double>& contact, double floor);

private:
  la::Vector _owned;                ///< owned multipliers of the last solve (equality rows first)
  la::Vector _restart_equality;     ///< equality multipliers by row id from a checkpoint; used once
  bool _equality_forgotten = false; ///< forget_equality() since the last solve
  std::map<int64_t, double> _contact;
  std::map<int64_t, std::array<double, 2>> _tangential; ///< by key, up to two tangents
  qp::QpState _state; ///< its x is always empty: the multipliers are kept above by row identity
};

/// The multipliers `lambda` (owned, of `feti`) of the rows id_begin <= id < id_end, replicated
/// on every rank (0 for ids that have no row); small: used for contact rows and checkpoints.
la::Vector multipliers_by_id(const FetiOperators& feti, const la::Vector& lambda, int64_t id_begin, int64_t id_end);
} // namespace feticon::dual
