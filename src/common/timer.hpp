#pragma once
/// @file Wall-clock timers per phase, accumulated by name (deal.II TimerOutput::Scope).

#include <chrono>
#include <map>
#include <string>
#include <vector>

namespace feticon
{
/// Accumulates wall time per named phase, in the order phases were first seen.
class TimerTable
{
public:
  void add(const std::string& phase, double seconds);
  /// Phases in first-seen order with their accumulated seconds.
  std::vector<std::pair<std::string, double>> entries() const;
  double total(const std::string& phase) const;
  /// A formatted table for the end-of-run summary.
  std::string format() const;

private:
  std::vector<std::string> _order;
  std::map<std::string, double> _seconds;
};

/// Adds the time between construction and destruction to a TimerTable entry.
class ScopedTimer
{
public:
  ScopedTimer(TimerTable& table, std::string phase);
  ~ScopedTimer();
  ScopedTimer(const ScopedTimer&) = delete;
  ScopedTimer& operator=(const ScopedTimer&) = delete;

private:
  TimerTable& _table;
  std::string _phase;
  std::chrono::steady_clock::time_point _start;
};

/// Seconds since `start` on the steady clock.
double seconds_since(std::chrono::steady_clock::time_point start);

/// Peak resident memory of this process in bytes (VmHWM from /proc/self/status).
long peak_memory_bytes();
} // namespace feticon
