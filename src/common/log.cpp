#include "common/log.hpp"

#include <algorithm>
#include <cstdint>
#include <iostream>
#include <mutex>

namespace feticon::log
{
namespace
{
Level current_level = Level::summary;
int current_rank = 0;
std::mutex pending_mutex;
/// A warning not yet taken: how often it was logged, and where first and last.
struct Pending
{
  std::string line;
  int64_t count = 0;
  std::string first, last;
};
std::vector<Pending> pending; ///< in the order first logged
std::string current_context;
} // namespace

void set_context(const std::string& context)
{
  const std::lock_guard lock(pending_mutex);
  current_context = context;
}

void set_level(Level l) { current_level = l; }
Level level() { return current_level; }
void set_rank(int rank) { current_rank = rank; }

void write(Level l, const std::string& line)
{
  if (current_rank != 0 || !enabled(l))
    return;
  // Progress goes to stdout; warnings to stderr so that they survive redirection of output.
  // One write of the whole line under a lock: the subdomain loops log from their threads, and
  // two warnings written piece by piece ran together into one line and an empty one (a fuzz
  // mutant of CalculiX's plate, whose two one-cell bodies both take their kernel from K).
  static std::mutex write_mutex;
  const std::string text = line + '\n';
  std::ostream& os = (l == Level::warning) ? std::cerr : std::cout;
  const std::lock_guard lock(write_mutex);
  os << text << std::flush;
}

void warning(const std::string& line)
{
  {
    const std::lock_guard lock(pending_mutex);
    const auto it = std::ranges::find(pending, line, &Pending::line);
    if (it != pending.end())
    {
      ++it->count;
      it->last = current_context;
      return;
    }
    pending.push_back({line, 1, current_context, current_context});
  }
  write(Level::warning, "warning: " + line);
}

std::vector<std::string> take_warnings()
{
  std::vector<Pending> taken;
  {
    const std::lock_guard lock(pending_mutex);
    taken.swap(pending);
  }
  std::vector<std::string> out;
  for (const Pending& p : taken)
  {
    if (p.count == 1)
    {
      out.push_back(p.line);
      continue;
    }
    out.push_back(p.line + " (" + std::to_string(p.count) + " times, first at " +
                  (p.first.empty() ? "set-up" : p.first) + ", last at " + (p.last.empty() ? "set-up" : p.last) + ")");
    write(Level::warning, "warning: " + out.back());
  }
  return out;
}
} // namespace feticon::log
