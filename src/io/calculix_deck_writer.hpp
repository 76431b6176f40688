#pragma once
/// @file What the two halves of the CalculiX deck writer (io/calculix_deck.hpp) share: the model
/// data (calculix_deck.cpp) and the steps with their loads, supports and temperatures
/// (calculix_deck_steps.cpp). Internal to them.

#include "common/error.hpp"
#include "fem/load_history.hpp"
#include "io/calculix_deck.hpp"

#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace feticon::io::deck_writer
{
/// A real number in CalculiX's free format: 13 significant digits fit its 20-character fields.
std::string number(double v);

/// Deck names: CalculiX upper-cases names and allows 80 characters; feticon's set names are
/// identifiers already, so only a prefix keeps them apart from the deck's own.
std::string deck_name(const std::string& prefix, const std::string& name);

/// Deck labels of the mesh nodes, n + 1, but for a pretension section's doubled nodes
/// (fem::Coupling::partners): CalculiX makes them again when it reads the section, so the deck
/// has no such node, its cells name the originals, and anything else that would name one is
/// refused in one line.
class DeckNodes
{
public:
  explicit DeckNodes(const fem::Problem& problem) : _original(problem.mesh.n_nodes(), -1)
  {
    for (const fem::Coupling& c : problem.couplings)
      if (c.kind == fem::CouplingKind::pretension)
      {
        const std::vector<int32_t>& olds = problem.mesh.node_set(c.nodes);
        const std::vector<int32_t>& news = problem.mesh.node_set(c.partners);
        for (size_t i = 0; i < news.size(); ++i)
          _original[news[i]] = olds[i];
      }
  }
  bool doubled(int32_t n) const { return _original[n] >= 0; }
  /// The label a cell names node n by: its original's for a doubled node.
  int64_t cell_label(int32_t n) const { return (doubled(n) ? _original[n] : n) + int64_t{1}; }
  /// @throws feticon::Error naming `what` for a doubled node
  int64_t label(int32_t n, const std::string& what) const
  {
    FETICON_CHECK(!doubled(n),
                  "calculix export: " << what << " names node " << n + 1
                                      << ", which a pretension section doubled; CalculiX doubles the "
                                         "section's nodes when it reads the deck, so a deck cannot name it");
    return n + int64_t{1};
  }
  /// The original of a doubled node (itself for the others).
  int32_t original(int32_t n) const { return doubled(n) ? _original[n] : n; }

private:
  std::vector<int32_t> _original; ///< per mesh node, -1 where it is no doubled node
};

/// The faces of a contact pair and its penalty stiffness.
struct ContactPairFaces
{
  std::vector<std::pair<int32_t, int>> slave, master;
  double stiffness;
};

/// Coulomb's mu of pair `pair` in step `step` (CalculixOptions::friction; 0 where not given).
double friction_of(const CalculixOptions& options, size_t step, size_t pair);

/// The slope K of `law` as a LINEAR law is written: its own where it is linear, else the penalty
/// of hard contact on `pair`.
double normal_slope(const fem::NormalLaw& law, const ContactPairFaces& pair);

/// The tie (index into fem::Problem::ties) of contact pair `pair` in the steps where it is tied:
/// a deck's pair that *CHANGE SURFACE BEHAVIOR turns between TIED and a contact law is a tie
/// and a pair, each out of force where the other is in (fem::Step::removed_ties,
/// removed_contacts). -1: the pair is never tied.
int32_t tie_of_pair(const fem::Problem& problem, int32_t pair);
/// Whether tie `tie` is a contact pair's tied state (tie_of_pair of some pair).
bool is_pair_tie(const fem::Problem& problem, int32_t tie);
/// Whether pair `pair` is tied in step `step` (0-based): its tie in force there.
bool tied_in_step(const fem::Problem& problem, int32_t pair, size_t step);
/// Pair `pair`'s normal law in step `step`: the step's fem::Step::changed_law, else its own.
fem::NormalLaw law_in_step(const fem::Problem& problem, int32_t pair, size_t step);
/// *SURFACE BEHAVIOR of a pair: TIED, or its law's pressure-overclosure (hard contact as the
/// penalty of `pair`'s slope; a node-to-surface LINEAR law with its tension sigma_inf).
void write_surface_behavior(std::ostream& out, const fem::NormalLaw& law, bool tied, const ContactPairFaces& pair,
                            bool node_to_segment);

/// A step's *TEMPERATURE, OP=NEW and its *TEMPERATURE, AMPLITUDE= blocks (calculix_deck_steps.cpp).
void write_temperatures(std::ostream& out, const fem::Problem& problem, const fem::Step& step, const DeckNodes& nodes);
/// The first *STEP: its increments, model changes, *BOUNDARY and *CLOAD blocks.
void write_step(std::ostream& out, const fem::Problem& problem, const CalculixOptions& options,
                const std::vector<ContactPairFaces>& pairs, const DeckNodes& nodes, CalculixDeckSummary& summary);
/// A later load stage as the next *STEP (calculix_deck_steps.cpp).
void write_later_step(std::ostream& out, const fem::Problem& problem, const fem::LoadHistory& history, int stage,
                      const CalculixOptions& options, const std::vector<ContactPairFaces>& pairs,
                      const DeckNodes& nodes, CalculixDeckSummary& summary);
} // namespace feticon::io::deck_writer
