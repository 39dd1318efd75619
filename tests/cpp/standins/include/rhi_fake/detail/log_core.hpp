// rhi-gen test stand-in (not the real ROS 2 code). Storage behind the fake RCLCPP_* macros:
// a fixed ring of formatted lines. Writing a line never allocates (vsnprintf into a fixed slot
// under a mutex), so logging from a driver's hot path stays allocation-free.
#pragma once

#include <atomic>
#include <cstdarg>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <mutex>

namespace rhi_fake {
namespace detail {

// Severity values are those of rcutils (RCUTILS_LOG_SEVERITY_*).
constexpr int kLogDebug = 10;
constexpr int kLogInfo = 20;
constexpr int kLogWarn = 30;
constexpr int kLogError = 40;
constexpr int kLogFatal = 50;

constexpr std::size_t kLogRingSize = 1024;      // lines kept (oldest overwritten)
constexpr std::size_t kLogTextSize = 512;       // bytes per line incl. NUL (longer text truncated)
constexpr std::size_t kLogNameSize = 96;        // bytes of logger name incl. NUL

struct LogSlot
{
  std::uint64_t seq = 0;   // 1-based sequence number; 0 = empty slot
  int severity = 0;
  bool truncated = false;
  char logger[kLogNameSize] = {};
  char text[kLogTextSize] = {};
};

struct LogCore
{
  std::mutex mutex;
  LogSlot ring[kLogRingSize];
  std::uint64_t next_seq = 1;                   // under mutex
  std::uint64_t counts[6] = {0, 0, 0, 0, 0, 0};  // index severity/10, under mutex
  // RHI_FAKE_LOG_ECHO=1 prints every line to stderr, as rcutils' console output would.
  std::atomic<bool> echo{std::getenv("RHI_FAKE_LOG_ECHO") != nullptr};
};

inline LogCore & log_core()
{
  static LogCore core;
  return core;
}

inline int severity_index(int severity)
{
  int i = severity / 10;
  return (i < 0) ? 0 : (i > 5 ? 5 : i);
}

inline void log_vwrite(int severity, const char * logger_name, const char * fmt, std::va_list args)
{
  LogCore & core = log_core();
  std::lock_guard<std::mutex> lock(core.mutex);
  LogSlot & slot = core.ring[core.next_seq % kLogRingSize];
  slot.seq = core.next_seq++;
  slot.severity = severity;
  const char * name = logger_name ? logger_name : "";
  std::size_t n = std::strlen(name);
  if (n >= kLogNameSize) {n = kLogNameSize - 1;}
  std::memcpy(slot.logger, name, n);
  slot.logger[n] = '\0';
  int written = std::vsnprintf(slot.text, kLogTextSize, fmt ? fmt : "", args);
  slot.truncated = written >= static_cast<int>(kLogTextSize);
  if (written < 0) {slot.text[0] = '\0';}
  core.counts[severity_index(severity)]++;
  if (core.echo.load(std::memory_order_relaxed)) {
    static const char * const names[6] = {"UNSET", "DEBUG", "INFO", "WARN", "ERROR", "FATAL"};
    std::fprintf(stderr, "[%s] [%s]: %s\n", names[severity_index(severity)], slot.logger, slot.text);
  }
}

// The printf attribute gives the same -Wformat checking as rcutils_log().
__attribute__((format(printf, 3, 4)))
inline void log_write(int severity, const char * logger_name, const char * fmt, ...)
{
  std::va_list args;
  va_start(args, fmt);
  log_vwrite(severity, logger_name, fmt, args);
  va_end(args);
}

}  // namespace detail
}  // namespace rhi_fake
