#pragma once
/// @file Checkpoint of a run after each converged load step, for `feticon run --restart`.
///
/// checkpoint.bin (written atomically, so it always holds the last converged step):
///   "FETICKP1", then length-prefixed blocks (int64 count, then the values): u_stacked,
///   lambda, contact slave nodes (int32), contact multipliers, and the JSON of the load
///   step and outer iteration records; completed_steps first.

#include "nonlinear/contact_solution.hpp"

#include <filesystem>

namespace feticon::app
{
void write_checkpoint(const std::filesystem::path& path, const nonlinear::ContactSolution& solution);
/// Fills restart, steps and history of `solution`; throws feticon::Error on a missing,
/// truncated or foreign file.
void read_checkpoint(const std::filesystem::path& path, nonlinear::ContactSolution& solution);
} // namespace feticon::app
