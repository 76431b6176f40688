#pragma once
/// @file The steps of a custom problem file: `supports:` and `loads:` (the first step),
/// `steps:` (every step, the first included, each carrying over what it does not give) and
/// `amplitudes:` (docs/usage.md, "Steps and amplitudes").

#include "fem/problem.hpp"
#include "io/problem_reader.hpp"

#include <yaml-cpp/yaml.h>

namespace feticon::io
{
/// The friction of `pair` (a contact pair, or a step's change of one), `friction: {model:
/// coulomb, coefficient: 0.3}` (or tresca with slip_bound, or none); none if it has none.
fem::Friction pair_friction(const YAML::Node& pair, const std::string& key, const ProblemReader& r);

/// The amplitude a load or support names (`amplitude: NAME`) or gives as its own table (then
/// kept in p.amplitudes under the entry's key); empty without one.
/// @throws feticon::Error naming the file and key for an unknown name or a malformed table
std::string amplitude_of(const YAML::Node& entry, const std::string& key, const ProblemReader& r, fem::Problem& p);

/// Fills p.steps and p.amplitudes from `root` (p.mesh read already; a step's `contact:` names
/// pairs of root's `contact:` list by index).
/// @throws feticon::Error naming the file and key of what is wrong
void read_steps(const YAML::Node& root, const ProblemReader& r, fem::Problem& p);
} // namespace feticon::io
