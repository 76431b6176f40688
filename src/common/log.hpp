#pragma once
/// @file Logging. Library code never writes std::cout directly; it logs here.
///
/// Levels follow MFEM's print levels: errors, warnings, summary, iterations.
/// Under MPI only rank 0 prints (set_rank()).

#include <sstream>
#include <string>
#include <vector>

namespace feticon::log
{
enum class Level
{
  quiet = 0,      ///< errors only
  warning = 1,    ///< + warnings
  summary = 2,    ///< + one line per phase / outer iteration (default)
  iterations = 3, ///< + one line per inner (QP) iteration
};

void set_level(Level level);
Level level();
/// Only rank 0 prints; other ranks stay silent whatever the level.
void set_rank(int rank);

void write(Level level, const std::string& line);
/// Writes "warning: line" and keeps `line` for take_warnings(), whatever the level and rank:
/// a warning from deep in the solver reaches the run's summary.json without a return path.
/// A line logged before is counted, not written again (an outer loop that meets the same
/// condition at every iteration would repeat it hundreds of times).
void warning(const std::string& line);
/// Where the run is, for the first and last occurrence of a repeated warning (the load-step
/// loop sets "load step 3, outer iteration 2"); empty: nowhere in particular.
void set_context(const std::string& context);
/// The warning lines since the last call, each once, in the order first logged; a line logged
/// n > 1 times ends "(n times, first at CONTEXT, last at CONTEXT)", and is written so to
/// stderr once more.
std::vector<std::string> take_warnings();
inline void info(const std::string& line) { write(Level::summary, line); }
inline void iteration(const std::string& line) { write(Level::iterations, line); }
inline bool enabled(Level l) { return static_cast<int>(l) <= static_cast<int>(level()); }
} // namespace feticon::log
