#include "common/log.hpp"

#include <algorithm>
#include <iostream>
#include <mutex>

namespace feticon::log
{
namespace
{
Level current_level = Level::summary;
int current_rank = 0;
std::mutex pending_mutex;
std::vector<std::string> pending; ///< warnings not yet taken, each once
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

void warning(const std::string& line)
{
  {
    const std::lock_guard lock(pending_mutex);
    if (std::ranges::find(pending, line) == pending.end())
      pending.push_back(line);
  }
  write(Level::warning, "warning: " + line);
}

std::vector<std::string> take_warnings()
{
  const std::lock_guard lock(pending_mutex);
  std::vector<std::string> out;
  out.swap(pending);
  return out;
}
} // namespace feticon::log
