#include "common/log.hpp"

#include <iostream>

namespace feticon::log
{
namespace
{
Level current_level = Level::summary;
int current_rank = 0;
} // namespace

void set_level(Level l) { current_level = l; }
Level level() { return current_level; }
void set_rank(int rank) { current_rank = rank; }

void write(Level l, const std::string& line)
{
  if (current_rank != 0 || !enabled(l))
    return;
  // Progress goes to stdout; warnings to stderr so that they survive redirection of output.
  std::ostream& os = (l == Level::warning) ? std::cerr : std::cout;
  os << line << '\n' << std::flush;
}
} // namespace feticon::log
