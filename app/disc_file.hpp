#pragma once
/// @file The discs of `feticon qp --discs FILE`: one disc a line, "i j radius", meaning
/// ||(x_i, x_j)|| <= radius, with i and j 1-based (as the rows of the Matrix Market files of
/// A, b, l and u). Blank lines and lines starting with '%' or '#' are skipped.
///
/// Example (x_1, x_2 in the unit disc, x_4, x_5 held at 0):
///   % i j radius
///   1 2 1.0
///   4 5 0

#include "la/types.hpp"
#include "qp/separable_constraints.hpp"

#include <string>
#include <vector>

namespace feticon::app
{
/// @brief Reads the discs of `path` for a QP of n components with bounds l and u.
/// @return the discs with 0-based indices.
/// Throws feticon::Error, one line "<path>:<line>: ..." naming the index or the radius, for a
/// line that is not "i j radius", an index outside 1..n, i = j, an index already in a disc, an
/// index with a finite bound in l or u, or a radius that is negative or not finite.
std::vector<qp::Disc> read_disc_file(const std::string& path, la::Index n, const la::Vector& lower,
                                     const la::Vector& upper);
} // namespace feticon::app
