// rhi-gen test stand-in (not the real ROS 2 code): the RCLCPP_* logging macros of ROS 2 Humble.
// Same macro names and parameters: RCLCPP_<SEV>(logger, fmt, ...), _ONCE, _EXPRESSION, _FUNCTION,
// _SKIPFIRST, _THROTTLE(logger, clock, duration_ms, ...), _SKIPFIRST_THROTTLE and the _STREAM
// variants, for SEV in DEBUG INFO WARN ERROR FATAL. As in Humble the first argument must be an
// rclcpp::Logger (static_assert), the format is printf-checked (-Wformat), and THROTTLE takes the
// clock *by reference* (`*node->get_clock()`, not the shared_ptr) and the period in milliseconds.
// Lines go to the rhi_fake log ring (see rhi_fake/logs.hpp). The printf-style macros never
// allocate; the _STREAM macros build a std::stringstream (they allocate, as in rclcpp).
// Every severity is captured, including DEBUG (a real logger at the default INFO level drops it).
#ifndef RCLCPP__LOGGING_HPP_
#define RCLCPP__LOGGING_HPP_

#include <atomic>
#include <cstdint>
#include <sstream>
#include <type_traits>

#include "rclcpp/logger.hpp"
#include "rhi_fake/detail/log_core.hpp"

#define RHI_RCLCPP_LOGGER_CHECK(logger) \
  static_assert( \
    ::std::is_same<typename std::remove_cv_t<typename std::remove_reference_t<decltype(logger)>>, \
    typename ::rclcpp::Logger>::value, \
    "First argument to logging macros must be an rclcpp::Logger")

// Time-based throttle shared by the _THROTTLE macros (rcutils semantics: log when
// now >= last_logged + duration, last_logged starting at 0 -- so with the system clock the first
// call logs, while with a fake time below `duration` it does not).
#define RHI_RCLCPP_THROTTLE_PASS(clock, duration, passed) \
  static std::atomic<std::int64_t> rhi_throttle_last_logged{0}; \
  bool passed = false; \
  { \
    auto & rhi_throttle_clock = clock; \
    const std::int64_t rhi_throttle_now = rhi_throttle_clock.now().nanoseconds(); \
    const std::int64_t rhi_throttle_period = static_cast<std::int64_t>(duration) * 1000000LL; \
    std::int64_t rhi_throttle_prev = rhi_throttle_last_logged.load(); \
    passed = rhi_throttle_now >= rhi_throttle_prev + rhi_throttle_period && \
      rhi_throttle_last_logged.compare_exchange_strong(rhi_throttle_prev, rhi_throttle_now); \
  }

// ---------------------------------------------------------------- DEBUG
#define RCLCPP_DEBUG(logger, ...) \
  do { \
    RHI_RCLCPP_LOGGER_CHECK(logger); \
    ::rhi_fake::detail::log_write(::rhi_fake::detail::kLogDebug, (logger).get_name(), __VA_ARGS__); \
  } while (0)

#define RCLCPP_DEBUG_ONCE(logger, ...) \
  do { \
    RHI_RCLCPP_LOGGER_CHECK(logger); \
    static std::atomic<bool> rhi_logged_once{false}; \
    if (!rhi_logged_once.exchange(true)) { \
      ::rhi_fake::detail::log_write(::rhi_fake::detail::kLogDebug, (logger).get_name(), __VA_ARGS__); \
    } \
  } while (0)

#define RCLCPP_DEBUG_EXPRESSION(logger, expression, ...) \
  do { \
    RHI_RCLCPP_LOGGER_CHECK(logger); \
    if (expression) { \
      ::rhi_fake::detail::log_write(::rhi_fake::detail::kLogDebug, (logger).get_name(), __VA_ARGS__); \
    } \
  } while (0)

#define RCLCPP_DEBUG_FUNCTION(logger, function, ...) \
  do { \
    RHI_RCLCPP_LOGGER_CHECK(logger); \
    if ((*function)()) { \
      ::rhi_fake::detail::log_write(::rhi_fake::detail::kLogDebug, (logger).get_name(), __VA_ARGS__); \
    } \
  } while (0)

#define RCLCPP_DEBUG_SKIPFIRST(logger, ...) \
  do { \
    RHI_RCLCPP_LOGGER_CHECK(logger); \
    static std::atomic<bool> rhi_first_skipped{false}; \
    if (rhi_first_skipped.exchange(true)) { \
      ::rhi_fake::detail::log_write(::rhi_fake::detail::kLogDebug, (logger).get_name(), __VA_ARGS__); \
    } \
  } while (0)

#define RCLCPP_DEBUG_THROTTLE(logger, clock, duration, ...) \
  do { \
    RHI_RCLCPP_LOGGER_CHECK(logger); \
    RHI_RCLCPP_THROTTLE_PASS(clock, duration, rhi_throttle_passed) \
    if (rhi_throttle_passed) { \
      ::rhi_fake::detail::log_write(::rhi_fake::detail::kLogDebug, (logger).get_name(), __VA_ARGS__); \
    } \
  } while (0)

#define RCLCPP_DEBUG_SKIPFIRST_THROTTLE(logger, clock, duration, ...) \
  do { \
    RHI_RCLCPP_LOGGER_CHECK(logger); \
    static std::atomic<bool> rhi_first_skipped{false}; \
    RHI_RCLCPP_THROTTLE_PASS(clock, duration, rhi_throttle_passed) \
    if (rhi_throttle_passed && rhi_first_skipped.exchange(true)) { \
      ::rhi_fake::detail::log_write(::rhi_fake::detail::kLogDebug, (logger).get_name(), __VA_ARGS__); \
    } \
  } while (0)

#define RCLCPP_DEBUG_STREAM(logger, stream_arg) \
  do { \
    RHI_RCLCPP_LOGGER_CHECK(logger); \
    std::stringstream rhi_ss; \
    rhi_ss << stream_arg; \
    ::rhi_fake::detail::log_write(::rhi_fake::detail::kLogDebug, (logger).get_name(), "%s", rhi_ss.str().c_str()); \
  } while (0)

#define RCLCPP_DEBUG_STREAM_ONCE(logger, stream_arg) \
  do { \
    RHI_RCLCPP_LOGGER_CHECK(logger); \
    static std::atomic<bool> rhi_logged_once{false}; \
    if (!rhi_logged_once.exchange(true)) { \
      std::stringstream rhi_ss; \
      rhi_ss << stream_arg; \
      ::rhi_fake::detail::log_write(::rhi_fake::detail::kLogDebug, (logger).get_name(), "%s", rhi_ss.str().c_str()); \
    } \
  } while (0)

#define RCLCPP_DEBUG_STREAM_EXPRESSION(logger, expression, stream_arg) \
  do { \
    RHI_RCLCPP_LOGGER_CHECK(logger); \
    if (expression) { \
      std::stringstream rhi_ss; \
      rhi_ss << stream_arg; \
      ::rhi_fake::detail::log_write(::rhi_fake::detail::kLogDebug, (logger).get_name(), "%s", rhi_ss.str().c_str()); \
    } \
  } while (0)

#define RCLCPP_DEBUG_STREAM_SKIPFIRST(logger, stream_arg) \
  do { \
    RHI_RCLCPP_LOGGER_CHECK(logger); \
    static std::atomic<bool> rhi_first_skipped{false}; \
    if (rhi_first_skipped.exchange(true)) { \
      std::stringstream rhi_ss; \
      rhi_ss << stream_arg; \
      ::rhi_fake::detail::log_write(::rhi_fake::detail::kLogDebug, (logger).get_name(), "%s", rhi_ss.str().c_str()); \
    } \
  } while (0)

#define RCLCPP_DEBUG_STREAM_THROTTLE(logger, clock, duration, stream_arg) \
  do { \
    RHI_RCLCPP_LOGGER_CHECK(logger); \
    RHI_RCLCPP_THROTTLE_PASS(clock, duration, rhi_throttle_passed) \
    if (rhi_throttle_passed) { \
      std::stringstream rhi_ss; \
      rhi_ss << stream_arg; \
      ::rhi_fake::detail::log_write(::rhi_fake::detail::kLogDebug, (logger).get_name(), "%s", rhi_ss.str().c_str()); \
    } \
  } while (0)

// ---------------------------------------------------------------- INFO
#define RCLCPP_INFO(logger, ...) \
  do { \
    RHI_RCLCPP_LOGGER_CHECK(logger); \
    ::rhi_fake::detail::log_write(::rhi_fake::detail::kLogInfo, (logger).get_name(), __VA_ARGS__); \
  } while (0)

#define RCLCPP_INFO_ONCE(logger, ...) \
  do { \
    RHI_RCLCPP_LOGGER_CHECK(logger); \
    static std::atomic<bool> rhi_logged_once{false}; \
    if (!rhi_logged_once.exchange(true)) { \
      ::rhi_fake::detail::log_write(::rhi_fake::detail::kLogInfo, (logger).get_name(), __VA_ARGS__); \
    } \
  } while (0)

#define RCLCPP_INFO_EXPRESSION(logger, expression, ...) \
  do { \
    RHI_RCLCPP_LOGGER_CHECK(logger); \
    if (expression) { \
      ::rhi_fake::detail::log_write(::rhi_fake::detail::kLogInfo, (logger).get_name(), __VA_ARGS__); \
    } \
  } while (0)

#define RCLCPP_INFO_FUNCTION(logger, function, ...) \
  do { \
    RHI_RCLCPP_LOGGER_CHECK(logger); \
    if ((*function)()) { \
      ::rhi_fake::detail::log_write(::rhi_fake::detail::kLogInfo, (logger).get_name(), __VA_ARGS__); \
    } \
  } while (0)

#define RCLCPP_INFO_SKIPFIRST(logger, ...) \
  do { \
    RHI_RCLCPP_LOGGER_CHECK(logger); \
    static std::atomic<bool> rhi_first_skipped{false}; \
    if (rhi_first_skipped.exchange(true)) { \
      ::rhi_fake::detail::log_write(::rhi_fake::detail::kLogInfo, (logger).get_name(), __VA_ARGS__); \
    } \
  } while (0)

#define RCLCPP_INFO_THROTTLE(logger, clock, duration, ...) \
  do { \
    RHI_RCLCPP_LOGGER_CHECK(logger); \
    RHI_RCLCPP_THROTTLE_PASS(clock, duration, rhi_throttle_passed) \
    if (rhi_throttle_passed) { \
      ::rhi_fake::detail::log_write(::rhi_fake::detail::kLogInfo, (logger).get_name(), __VA_ARGS__); \
    } \
  } while (0)

#define RCLCPP_INFO_SKIPFIRST_THROTTLE(logger, clock, duration, ...) \
  do { \
    RHI_RCLCPP_LOGGER_CHECK(logger); \
    static std::atomic<bool> rhi_first_skipped{false}; \
    RHI_RCLCPP_THROTTLE_PASS(clock, duration, rhi_throttle_passed) \
    if (rhi_throttle_passed && rhi_first_skipped.exchange(true)) { \
      ::rhi_fake::detail::log_write(::rhi_fake::detail::kLogInfo, (logger).get_name(), __VA_ARGS__); \
    } \
  } while (0)

#define RCLCPP_INFO_STREAM(logger, stream_arg) \
  do { \
    RHI_RCLCPP_LOGGER_CHECK(logger); \
    std::stringstream rhi_ss; \
    rhi_ss << stream_arg; \
    ::rhi_fake::detail::log_write(::rhi_fake::detail::kLogInfo, (logger).get_name(), "%s", rhi_ss.str().c_str()); \
  } while (0)

#define RCLCPP_INFO_STREAM_ONCE(logger, stream_arg) \
  do { \
    RHI_RCLCPP_LOGGER_CHECK(logger); \
    static std::atomic<bool> rhi_logged_once{false}; \
    if (!rhi_logged_once.exchange(true)) { \
      std::stringstream rhi_ss; \
      rhi_ss << stream_arg; \
      ::rhi_fake::detail::log_write(::rhi_fake::detail::kLogInfo, (logger).get_name(), "%s", rhi_ss.str().c_str()); \
    } \
  } while (0)

#define RCLCPP_INFO_STREAM_EXPRESSION(logger, expression, stream_arg) \
  do { \
    RHI_RCLCPP_LOGGER_CHECK(logger); \
    if (expression) { \
      std::stringstream rhi_ss; \
      rhi_ss << stream_arg; \
      ::rhi_fake::detail::log_write(::rhi_fake::detail::kLogInfo, (logger).get_name(), "%s", rhi_ss.str().c_str()); \
    } \
  } while (0)

#define RCLCPP_INFO_STREAM_SKIPFIRST(logger, stream_arg) \
  do { \
    RHI_RCLCPP_LOGGER_CHECK(logger); \
    static std::atomic<bool> rhi_first_skipped{false}; \
    if (rhi_first_skipped.exchange(true)) { \
      std::stringstream rhi_ss; \
      rhi_ss << stream_arg; \
      ::rhi_fake::detail::log_write(::rhi_fake::detail::kLogInfo, (logger).get_name(), "%s", rhi_ss.str().c_str()); \
    } \
  } while (0)

#define RCLCPP_INFO_STREAM_THROTTLE(logger, clock, duration, stream_arg) \
  do { \
    RHI_RCLCPP_LOGGER_CHECK(logger); \
    RHI_RCLCPP_THROTTLE_PASS(clock, duration, rhi_throttle_passed) \
    if (rhi_throttle_passed) { \
      std::stringstream rhi_ss; \
      rhi_ss << stream_arg; \
      ::rhi_fake::detail::log_write(::rhi_fake::detail::kLogInfo, (logger).get_name(), "%s", rhi_ss.str().c_str()); \
    } \
  } while (0)

// ---------------------------------------------------------------- WARN
#define RCLCPP_WARN(logger, ...) \
  do { \
    RHI_RCLCPP_LOGGER_CHECK(logger); \
    ::rhi_fake::detail::log_write(::rhi_fake::detail::kLogWarn, (logger).get_name(), __VA_ARGS__); \
  } while (0)

#define RCLCPP_WARN_ONCE(logger, ...) \
  do { \
    RHI_RCLCPP_LOGGER_CHECK(logger); \
    static std::atomic<bool> rhi_logged_once{false}; \
    if (!rhi_logged_once.exchange(true)) { \
      ::rhi_fake::detail::log_write(::rhi_fake::detail::kLogWarn, (logger).get_name(), __VA_ARGS__); \
    } \
  } while (0)

#define RCLCPP_WARN_EXPRESSION(logger, expression, ...) \
  do { \
    RHI_RCLCPP_LOGGER_CHECK(logger); \
    if (expression) { \
      ::rhi_fake::detail::log_write(::rhi_fake::detail::kLogWarn, (logger).get_name(), __VA_ARGS__); \
    } \
  } while (0)

#define RCLCPP_WARN_FUNCTION(logger, function, ...) \
  do { \
    RHI_RCLCPP_LOGGER_CHECK(logger); \
    if ((*function)()) { \
      ::rhi_fake::detail::log_write(::rhi_fake::detail::kLogWarn, (logger).get_name(), __VA_ARGS__); \
    } \
  } while (0)

#define RCLCPP_WARN_SKIPFIRST(logger, ...) \
  do { \
    RHI_RCLCPP_LOGGER_CHECK(logger); \
    static std::atomic<bool> rhi_first_skipped{false}; \
    if (rhi_first_skipped.exchange(true)) { \
      ::rhi_fake::detail::log_write(::rhi_fake::detail::kLogWarn, (logger).get_name(), __VA_ARGS__); \
    } \
  } while (0)

#define RCLCPP_WARN_THROTTLE(logger, clock, duration, ...) \
  do { \
    RHI_RCLCPP_LOGGER_CHECK(logger); \
    RHI_RCLCPP_THROTTLE_PASS(clock, duration, rhi_throttle_passed) \
    if (rhi_throttle_passed) { \
      ::rhi_fake::detail::log_write(::rhi_fake::detail::kLogWarn, (logger).get_name(), __VA_ARGS__); \
    } \
  } while (0)

#define RCLCPP_WARN_SKIPFIRST_THROTTLE(logger, clock, duration, ...) \
  do { \
    RHI_RCLCPP_LOGGER_CHECK(logger); \
    static std::atomic<bool> rhi_first_skipped{false}; \
    RHI_RCLCPP_THROTTLE_PASS(clock, duration, rhi_throttle_passed) \
    if (rhi_throttle_passed && rhi_first_skipped.exchange(true)) { \
      ::rhi_fake::detail::log_write(::rhi_fake::detail::kLogWarn, (logger).get_name(), __VA_ARGS__); \
    } \
  } while (0)

#define RCLCPP_WARN_STREAM(logger, stream_arg) \
  do { \
    RHI_RCLCPP_LOGGER_CHECK(logger); \
    std::stringstream rhi_ss; \
    rhi_ss << stream_arg; \
    ::rhi_fake::detail::log_write(::rhi_fake::detail::kLogWarn, (logger).get_name(), "%s", rhi_ss.str().c_str()); \
  } while (0)

#define RCLCPP_WARN_STREAM_ONCE(logger, stream_arg) \
  do { \
    RHI_RCLCPP_LOGGER_CHECK(logger); \
    static std::atomic<bool> rhi_logged_once{false}; \
    if (!rhi_logged_once.exchange(true)) { \
      std::stringstream rhi_ss; \
      rhi_ss << stream_arg; \
      ::rhi_fake::detail::log_write(::rhi_fake::detail::kLogWarn, (logger).get_name(), "%s", rhi_ss.str().c_str()); \
    } \
  } while (0)

#define RCLCPP_WARN_STREAM_EXPRESSION(logger, expression, stream_arg) \
  do { \
    RHI_RCLCPP_LOGGER_CHECK(logger); \
    if (expression) { \
      std::stringstream rhi_ss; \
      rhi_ss << stream_arg; \
      ::rhi_fake::detail::log_write(::rhi_fake::detail::kLogWarn, (logger).get_name(), "%s", rhi_ss.str().c_str()); \
    } \
  } while (0)

#define RCLCPP_WARN_STREAM_SKIPFIRST(logger, stream_arg) \
  do { \
    RHI_RCLCPP_LOGGER_CHECK(logger); \
    static std::atomic<bool> rhi_first_skipped{false}; \
    if (rhi_first_skipped.exchange(true)) { \
      std::stringstream rhi_ss; \
      rhi_ss << stream_arg; \
      ::rhi_fake::detail::log_write(::rhi_fake::detail::kLogWarn, (logger).get_name(), "%s", rhi_ss.str().c_str()); \
    } \
  } while (0)

#define RCLCPP_WARN_STREAM_THROTTLE(logger, clock, duration, stream_arg) \
  do { \
    RHI_RCLCPP_LOGGER_CHECK(logger); \
    RHI_RCLCPP_THROTTLE_PASS(clock, duration, rhi_throttle_passed) \
    if (rhi_throttle_passed) { \
      std::stringstream rhi_ss; \
      rhi_ss << stream_arg; \
      ::rhi_fake::detail::log_write(::rhi_fake::detail::kLogWarn, (logger).get_name(), "%s", rhi_ss.str().c_str()); \
    } \
  } while (0)

// ---------------------------------------------------------------- ERROR
#define RCLCPP_ERROR(logger, ...) \
  do { \
    RHI_RCLCPP_LOGGER_CHECK(logger); \
    ::rhi_fake::detail::log_write(::rhi_fake::detail::kLogError, (logger).get_name(), __VA_ARGS__); \
  } while (0)

#define RCLCPP_ERROR_ONCE(logger, ...) \
  do { \
    RHI_RCLCPP_LOGGER_CHECK(logger); \
    static std::atomic<bool> rhi_logged_once{false}; \
    if (!rhi_logged_once.exchange(true)) { \
      ::rhi_fake::detail::log_write(::rhi_fake::detail::kLogError, (logger).get_name(), __VA_ARGS__); \
    } \
  } while (0)

#define RCLCPP_ERROR_EXPRESSION(logger, expression, ...) \
  do { \
    RHI_RCLCPP_LOGGER_CHECK(logger); \
    if (expression) { \
      ::rhi_fake::detail::log_write(::rhi_fake::detail::kLogError, (logger).get_name(), __VA_ARGS__); \
    } \
  } while (0)

#define RCLCPP_ERROR_FUNCTION(logger, function, ...) \
  do { \
    RHI_RCLCPP_LOGGER_CHECK(logger); \
    if ((*function)()) { \
      ::rhi_fake::detail::log_write(::rhi_fake::detail::kLogError, (logger).get_name(), __VA_ARGS__); \
    } \
  } while (0)

#define RCLCPP_ERROR_SKIPFIRST(logger, ...) \
  do { \
    RHI_RCLCPP_LOGGER_CHECK(logger); \
    static std::atomic<bool> rhi_first_skipped{false}; \
    if (rhi_first_skipped.exchange(true)) { \
      ::rhi_fake::detail::log_write(::rhi_fake::detail::kLogError, (logger).get_name(), __VA_ARGS__); \
    } \
  } while (0)

#define RCLCPP_ERROR_THROTTLE(logger, clock, duration, ...) \
  do { \
    RHI_RCLCPP_LOGGER_CHECK(logger); \
    RHI_RCLCPP_THROTTLE_PASS(clock, duration, rhi_throttle_passed) \
    if (rhi_throttle_passed) { \
      ::rhi_fake::detail::log_write(::rhi_fake::detail::kLogError, (logger).get_name(), __VA_ARGS__); \
    } \
  } while (0)

#define RCLCPP_ERROR_SKIPFIRST_THROTTLE(logger, clock, duration, ...) \
  do { \
    RHI_RCLCPP_LOGGER_CHECK(logger); \
    static std::atomic<bool> rhi_first_skipped{false}; \
    RHI_RCLCPP_THROTTLE_PASS(clock, duration, rhi_throttle_passed) \
    if (rhi_throttle_passed && rhi_first_skipped.exchange(true)) { \
      ::rhi_fake::detail::log_write(::rhi_fake::detail::kLogError, (logger).get_name(), __VA_ARGS__); \
    } \
  } while (0)

#define RCLCPP_ERROR_STREAM(logger, stream_arg) \
  do { \
    RHI_RCLCPP_LOGGER_CHECK(logger); \
    std::stringstream rhi_ss; \
    rhi_ss << stream_arg; \
    ::rhi_fake::detail::log_write(::rhi_fake::detail::kLogError, (logger).get_name(), "%s", rhi_ss.str().c_str()); \
  } while (0)

#define RCLCPP_ERROR_STREAM_ONCE(logger, stream_arg) \
  do { \
    RHI_RCLCPP_LOGGER_CHECK(logger); \
    static std::atomic<bool> rhi_logged_once{false}; \
    if (!rhi_logged_once.exchange(true)) { \
      std::stringstream rhi_ss; \
      rhi_ss << stream_arg; \
      ::rhi_fake::detail::log_write(::rhi_fake::detail::kLogError, (logger).get_name(), "%s", rhi_ss.str().c_str()); \
    } \
  } while (0)

#define RCLCPP_ERROR_STREAM_EXPRESSION(logger, expression, stream_arg) \
  do { \
    RHI_RCLCPP_LOGGER_CHECK(logger); \
    if (expression) { \
      std::stringstream rhi_ss; \
      rhi_ss << stream_arg; \
      ::rhi_fake::detail::log_write(::rhi_fake::detail::kLogError, (logger).get_name(), "%s", rhi_ss.str().c_str()); \
    } \
  } while (0)

#define RCLCPP_ERROR_STREAM_SKIPFIRST(logger, stream_arg) \
  do { \
    RHI_RCLCPP_LOGGER_CHECK(logger); \
    static std::atomic<bool> rhi_first_skipped{false}; \
    if (rhi_first_skipped.exchange(true)) { \
      std::stringstream rhi_ss; \
      rhi_ss << stream_arg; \
      ::rhi_fake::detail::log_write(::rhi_fake::detail::kLogError, (logger).get_name(), "%s", rhi_ss.str().c_str()); \
    } \
  } while (0)

#define RCLCPP_ERROR_STREAM_THROTTLE(logger, clock, duration, stream_arg) \
  do { \
    RHI_RCLCPP_LOGGER_CHECK(logger); \
    RHI_RCLCPP_THROTTLE_PASS(clock, duration, rhi_throttle_passed) \
    if (rhi_throttle_passed) { \
      std::stringstream rhi_ss; \
      rhi_ss << stream_arg; \
      ::rhi_fake::detail::log_write(::rhi_fake::detail::kLogError, (logger).get_name(), "%s", rhi_ss.str().c_str()); \
    } \
  } while (0)

// ---------------------------------------------------------------- FATAL
#define RCLCPP_FATAL(logger, ...) \
  do { \
    RHI_RCLCPP_LOGGER_CHECK(logger); \
    ::rhi_fake::detail::log_write(::rhi_fake::detail::kLogFatal, (logger).get_name(), __VA_ARGS__); \
  } while (0)

#define RCLCPP_FATAL_ONCE(logger, ...) \
  do { \
    RHI_RCLCPP_LOGGER_CHECK(logger); \
    static std::atomic<bool> rhi_logged_once{false}; \
    if (!rhi_logged_once.exchange(true)) { \
      ::rhi_fake::detail::log_write(::rhi_fake::detail::kLogFatal, (logger).get_name(), __VA_ARGS__); \
    } \
  } while (0)

#define RCLCPP_FATAL_EXPRESSION(logger, expression, ...) \
  do { \
    RHI_RCLCPP_LOGGER_CHECK(logger); \
    if (expression) { \
      ::rhi_fake::detail::log_write(::rhi_fake::detail::kLogFatal, (logger).get_name(), __VA_ARGS__); \
    } \
  } while (0)

#define RCLCPP_FATAL_FUNCTION(logger, function, ...) \
  do { \
    RHI_RCLCPP_LOGGER_CHECK(logger); \
    if ((*function)()) { \
      ::rhi_fake::detail::log_write(::rhi_fake::detail::kLogFatal, (logger).get_name(), __VA_ARGS__); \
    } \
  } while (0)

#define RCLCPP_FATAL_SKIPFIRST(logger, ...) \
  do { \
    RHI_RCLCPP_LOGGER_CHECK(logger); \
    static std::atomic<bool> rhi_first_skipped{false}; \
    if (rhi_first_skipped.exchange(true)) { \
      ::rhi_fake::detail::log_write(::rhi_fake::detail::kLogFatal, (logger).get_name(), __VA_ARGS__); \
    } \
  } while (0)

#define RCLCPP_FATAL_THROTTLE(logger, clock, duration, ...) \
  do { \
    RHI_RCLCPP_LOGGER_CHECK(logger); \
    RHI_RCLCPP_THROTTLE_PASS(clock, duration, rhi_throttle_passed) \
    if (rhi_throttle_passed) { \
      ::rhi_fake::detail::log_write(::rhi_fake::detail::kLogFatal, (logger).get_name(), __VA_ARGS__); \
    } \
  } while (0)

#define RCLCPP_FATAL_SKIPFIRST_THROTTLE(logger, clock, duration, ...) \
  do { \
    RHI_RCLCPP_LOGGER_CHECK(logger); \
    static std::atomic<bool> rhi_first_skipped{false}; \
    RHI_RCLCPP_THROTTLE_PASS(clock, duration, rhi_throttle_passed) \
    if (rhi_throttle_passed && rhi_first_skipped.exchange(true)) { \
      ::rhi_fake::detail::log_write(::rhi_fake::detail::kLogFatal, (logger).get_name(), __VA_ARGS__); \
    } \
  } while (0)

#define RCLCPP_FATAL_STREAM(logger, stream_arg) \
  do { \
    RHI_RCLCPP_LOGGER_CHECK(logger); \
    std::stringstream rhi_ss; \
    rhi_ss << stream_arg; \
    ::rhi_fake::detail::log_write(::rhi_fake::detail::kLogFatal, (logger).get_name(), "%s", rhi_ss.str().c_str()); \
  } while (0)

#define RCLCPP_FATAL_STREAM_ONCE(logger, stream_arg) \
  do { \
    RHI_RCLCPP_LOGGER_CHECK(logger); \
    static std::atomic<bool> rhi_logged_once{false}; \
    if (!rhi_logged_once.exchange(true)) { \
      std::stringstream rhi_ss; \
      rhi_ss << stream_arg; \
      ::rhi_fake::detail::log_write(::rhi_fake::detail::kLogFatal, (logger).get_name(), "%s", rhi_ss.str().c_str()); \
    } \
  } while (0)

#define RCLCPP_FATAL_STREAM_EXPRESSION(logger, expression, stream_arg) \
  do { \
    RHI_RCLCPP_LOGGER_CHECK(logger); \
    if (expression) { \
      std::stringstream rhi_ss; \
      rhi_ss << stream_arg; \
      ::rhi_fake::detail::log_write(::rhi_fake::detail::kLogFatal, (logger).get_name(), "%s", rhi_ss.str().c_str()); \
    } \
  } while (0)

#define RCLCPP_FATAL_STREAM_SKIPFIRST(logger, stream_arg) \
  do { \
    RHI_RCLCPP_LOGGER_CHECK(logger); \
    static std::atomic<bool> rhi_first_skipped{false}; \
    if (rhi_first_skipped.exchange(true)) { \
      std::stringstream rhi_ss; \
      rhi_ss << stream_arg; \
      ::rhi_fake::detail::log_write(::rhi_fake::detail::kLogFatal, (logger).get_name(), "%s", rhi_ss.str().c_str()); \
    } \
  } while (0)

#define RCLCPP_FATAL_STREAM_THROTTLE(logger, clock, duration, stream_arg) \
  do { \
    RHI_RCLCPP_LOGGER_CHECK(logger); \
    RHI_RCLCPP_THROTTLE_PASS(clock, duration, rhi_throttle_passed) \
    if (rhi_throttle_passed) { \
      std::stringstream rhi_ss; \
      rhi_ss << stream_arg; \
      ::rhi_fake::detail::log_write(::rhi_fake::detail::kLogFatal, (logger).get_name(), "%s", rhi_ss.str().c_str()); \
    } \
  } while (0)

#endif  // RCLCPP__LOGGING_HPP_
