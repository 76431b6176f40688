#pragma once
/// @file Logging. Library code never writes std::cout directly; it logs here.
///
/// Levels follow MFEM's print levels: errors, warnings, summary, iterations.
/// Under MPI only rank 0 prints (set_rank()).

#include <sstream>
#include <string>

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
inline void warning(const std::string& line) { write(Level::warning, "warning: " + line); }
inline void info(const std::string& line) { write(Level::summary, line); }
inline void iteration(const std::string& line) { write(Level::iterations, line); }
inline bool enabled(Level l) { return static_cast<int>(l) <= static_cast<int>(level()); }
} // namespace feticon::log
