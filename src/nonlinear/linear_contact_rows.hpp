#pragma once
/// @file The contact rows of a linear (small-displacement) run: the candidates within the
/// search distance, and the subset the QP gets.
///
/// A linear run has one set of candidate rows, those of every slave node within the search
/// distance of the master surface in the reference configuration (the automatic distance is
/// the largest master face diagonal, so on a graded mesh the band reaches far beyond the
/// contact zone). Rows that stay inactive do not change the answer, but they are not free:
/// on the Hertz mesh at refinement 2, the rows of nodes 5-40 mm away from the master surface
/// (58 of 1 146 dual rows) raised the largest eigenvalue of the preconditioned dual operator on
/// the solution's face from 9.3 to 76 and doubled the MPRGP steps (docs/contact.md, "The far
/// contact rows of a linear run").
///
/// So the QP gets only the rows near contact, g_i < max(g_min, 0) + band d_i (d_i the
/// longer diagonal of the row's master face, g_min the smallest gap of the row's pair), with the linearized gaps c_i - B_i u of the
/// current u. After each QP, expand(u) checks the other candidates' linearized gaps: if one
/// is negative (a node would penetrate), every candidate within the band of contact at u is
/// added and another QP follows; if none is, the answer satisfies every candidate row with a
/// zero multiplier on the left-out ones, so it is the solution of the QP with all of them
/// (a convex QP whose solution with fewer constraints satisfies the others).

#include "contact/contact_constraints.hpp"
#include "mesh/mesh.hpp"

#include <vector>

namespace feticon::nonlinear
{
class LinearContactRows
{
public:
  /// @param masters    the master face set of each pair (candidates.pair indexes it)
  /// @param candidates rows at the reference configuration (u = 0), pair after pair
  /// @param band       the near-contact band in master face diagonals
  LinearContactRows(const mesh::Mesh& mesh, const std::vector<std::string>& masters,
                    contact::ContactConstraints candidates, double band);

  /// The selected rows with c = c_ref - B u (u global, 3 per node).
  contact::ContactConstraints selected_rows(const la::Vector& u) const;
  /// Adds the candidates within the band of contact at u if one of the left-out ones has a
  /// negative linearized gap there; returns whether it added any (another QP is needed).
  bool expand(const la::Vector& u);
  /// Every candidate row (reference gaps), and the multipliers of `selected` (by key)
  /// spread over them (matched by key), zero on the left-out ones: the output of a converged run.
  const contact::ContactConstraints& candidates() const { return _candidates; }
  la::Vector all_multipliers(const contact::ContactConstraints& selected, const la::Vector& lambda) const;

  /// @brief Which pairs are in force (a step's model change); empty: all. Rows of the others are
  /// neither selected nor added.
  void set_pairs_in_force(std::vector<char> in_force) { _in_force = std::move(in_force); }

  int64_t n_selected() const;
  /// The candidates selected so far, by index (what a checkpoint keeps: the rows expand added
  /// are those of the uninterrupted run, which a restart's QPs must start from).
  std::vector<int32_t> selected_indices() const;
  /// @brief Selects these candidates (and no others).
  /// @throws feticon::Error for an index out of range (a checkpoint of another model).
  void select(const std::vector<int32_t>& indices);
  int64_t n_candidates() const { return _candidates.n_rows(); }

private:
  contact::ContactConstraints subset(const std::vector<char>& keep, const la::Vector& u) const;
  bool in_force(la::Index row) const { return _in_force.empty() || _in_force[_candidates.pair[row]]; }

  contact::ContactConstraints _candidates;
  std::vector<double> _band_gap; ///< band d_i per row (m)
  std::vector<char> _selected;
  std::vector<char> _in_force; ///< per pair; empty: all
};
} // namespace feticon::nonlinear
