// rhi-gen test hooks (test code only; generated drivers never include rhi_fake/).
// Inspect what drivers logged through the fake RCLCPP_* macros. Thread-safe.
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#include "rhi_fake/detail/log_core.hpp"

namespace rhi_fake {
namespace logs {

enum class Severity : int
{
  Debug = detail::kLogDebug,
  Info = detail::kLogInfo,
  Warn = detail::kLogWarn,
  Error = detail::kLogError,
  Fatal = detail::kLogFatal,
};

struct Line
{
  std::uint64_t seq;       // increasing, 1-based, never reused until clear()
  Severity severity;
  std::string logger;      // logger name (e.g. "g1_hardware_interface")
  std::string text;        // formatted message (at most 511 bytes)
  bool truncated;          // text was longer and got cut
};

/// Lines still in the ring (the newest detail::kLogRingSize), oldest first.
inline std::vector<Line> lines()
{
  auto & core = detail::log_core();
  std::lock_guard<std::mutex> lock(core.mutex);
  std::vector<Line> out;
  std::uint64_t first = core.next_seq > detail::kLogRingSize ? core.next_seq - detail::kLogRingSize : 1;
  for (std::uint64_t s = first; s < core.next_seq; ++s) {
    const auto & slot = core.ring[s % detail::kLogRingSize];
    if (slot.seq != s) {continue;}
    out.push_back(Line{slot.seq, static_cast<Severity>(slot.severity), slot.logger, slot.text,
        slot.truncated});
  }
  return out;
}

/// Number of lines logged with exactly this severity since the last clear() (not limited by the ring).
inline std::size_t count(Severity severity)
{
  auto & core = detail::log_core();
  std::lock_guard<std::mutex> lock(core.mutex);
  return static_cast<std::size_t>(core.counts[detail::severity_index(static_cast<int>(severity))]);
}

/// Number of lines of any severity since the last clear().
inline std::size_t count_all()
{
  auto & core = detail::log_core();
  std::lock_guard<std::mutex> lock(core.mutex);
  std::uint64_t total = 0;
  for (auto c : core.counts) {total += c;}
  return static_cast<std::size_t>(total);
}

/// Number of lines in the ring whose text contains `needle` and whose severity is >= min_severity.
inline std::size_t count_containing(std::string_view needle, Severity min_severity = Severity::Debug)
{
  std::size_t n = 0;
  for (const auto & line : lines()) {
    if (static_cast<int>(line.severity) >= static_cast<int>(min_severity) &&
      line.text.find(needle) != std::string::npos)
    {
      ++n;
    }
  }
  return n;
}

/// True if a line in the ring contains `needle` with severity >= min_severity.
inline bool contains(std::string_view needle, Severity min_severity = Severity::Debug)
{
  return count_containing(needle, min_severity) > 0;
}

/// Polls contains() until it is true or `timeout` passes (for lines logged by driver threads).
inline bool wait_for(
  std::string_view needle, std::chrono::milliseconds timeout,
  Severity min_severity = Severity::Debug)
{
  auto deadline = std::chrono::steady_clock::now() + timeout;
  while (true) {
    if (contains(needle, min_severity)) {return true;}
    if (std::chrono::steady_clock::now() >= deadline) {return false;}
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
}

/// Forget all lines and counters.
inline void clear()
{
  auto & core = detail::log_core();
  std::lock_guard<std::mutex> lock(core.mutex);
  for (auto & slot : core.ring) {slot.seq = 0;}
  for (auto & c : core.counts) {c = 0;}
  core.next_seq = 1;
}

/// Also print every line to stderr as it is logged (off by default).
inline void set_echo(bool on)
{
  detail::log_core().echo.store(on);
}

inline const char * severity_name(Severity s)
{
  switch (s) {
    case Severity::Debug: return "DEBUG";
    case Severity::Info: return "INFO";
    case Severity::Warn: return "WARN";
    case Severity::Error: return "ERROR";
    case Severity::Fatal: return "FATAL";
  }
  return "?";
}

}  // namespace logs
}  // namespace rhi_fake
