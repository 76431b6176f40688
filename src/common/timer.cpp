#include "common/timer.hpp"

#include <fstream>
#include <iomanip>
#include <sstream>

namespace feticon
{
void TimerTable::add(const std::string& phase, double seconds)
{
  if (_seconds.find(phase) == _seconds.end())
    _order.push_back(phase);
  _seconds[phase] += seconds;
}

std::vector<std::pair<std::string, double>> TimerTable::entries() const
{
  std::vector<std::pair<std::string, double>> out;
  for (const auto& name : _order)
    out.emplace_back(name, _seconds.at(name));
  return out;
}

double TimerTable::total(const std::string& phase) const
{
  auto it = _seconds.find(phase);
  return it == _seconds.end() ? 0.0 : it->second;
}

std::string TimerTable::format() const
{
  std::ostringstream os;
  os << std::left << std::setw(28) << "phase" << std::right << std::setw(12) << "seconds\n";
  for (const auto& [name, seconds] : entries())
    os << std::left << std::setw(28) << name << std::right << std::setw(11) << std::fixed << std::setprecision(3)
       << seconds << '\n';
  return os.str();
}

ScopedTimer::ScopedTimer(TimerTable& table, std::string phase)
    : _table(table), _phase(std::move(phase)), _start(std::chrono::steady_clock::now())
{
}

ScopedTimer::~ScopedTimer() { _table.add(_phase, seconds_since(_start)); }

double seconds_since(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

namespace
{
/// The value (KiB in the file) of the line `key` of a /proc file, in bytes; 0 if absent.
long proc_bytes(const char* path, const std::string& key)
{
  std::ifstream file(path);
  std::string line;
  while (std::getline(file, line))
    if (line.rfind(key, 0) == 0)
    {
      std::istringstream is(line.substr(key.size()));
      long kib = 0;
      is >> kib;
      return kib * 1024;
    }
  return 0;
}
} // namespace

long peak_memory_bytes() { return proc_bytes("/proc/self/status", "VmHWM:"); }
} // namespace feticon
