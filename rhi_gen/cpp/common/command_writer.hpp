// Copyright the rhi-gen authors
// SPDX-License-Identifier: Apache-2.0
//
// rhi-gen copies this file into every generated package that needs it, below the package's banner.

#ifndef ROBOT_HARDWARE_INTERFACE__COMMON__COMMAND_WRITER_HPP_
#define ROBOT_HARDWARE_INTERFACE__COMMON__COMMAND_WRITER_HPP_

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <thread>
#include <utility>

namespace robot_hardware_interface
{

// The command writer of the on_write mode: a thread of its own that write() wakes, so that a
// command leaves when it is built instead of on the writer's next tick (which costs up to a
// period of latency). What it sends is the transport's send function, unchanged: it takes
// DriverCore::next_command(), so the safe start and every hold are the timer mode's.
//   - write() only raises a flag and signals (notify()): it never waits for the network, and for
//     the mutex only while the writer checks the flag (a few instructions).
//   - Rate limit: never more than one command per period on average, never two less than half a
//     period apart (a virtual schedule: a send is allowed from half a period before its turn), so
//     the robot never sees a faster command rate than the timer mode gives it. A write() that
//     comes sooner is not answered on its own; its command leaves with the next write()'s.
//   - Fallback: when write() has not woken it for two periods (the controller manager is late or
//     stalled, or ros2_control stopped calling write() after on_error), it sends every period, as
//     the timer mode does, so the holds keep flowing until write() wakes it again.
//   - No allocation after start().
class OnWriteCommandWriter
{
public:
  OnWriteCommandWriter() = default;
  OnWriteCommandWriter(const OnWriteCommandWriter &) = delete;
  OnWriteCommandWriter & operator=(const OnWriteCommandWriter &) = delete;
  ~OnWriteCommandWriter() {stop();}

  // on_activate: starts the thread; `send` is called on it, never twice at once. May throw
  // (std::system_error when no thread can be created).
  template<typename Send>
  void start(uint64_t period_us, Send && send)
  {
    stop();
    {
      std::lock_guard<std::mutex> lock(mutex_);
      stopping_ = false;
      woken_ = false;
    }
    const std::chrono::microseconds period(period_us);
    thread_ = std::thread(
      [this, period, send = std::forward<Send>(send)]() mutable {run(period, send);});
  }

  // write(), after the command is published: the writer sends it now (or at the rate limit).
  void notify() noexcept
  {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      woken_ = true;
    }
    wake_.notify_one();
  }

  // on_deactivate: once this returns, `send` is never called again.
  void stop()
  {
    if (!thread_.joinable()) {
      return;
    }
    {
      std::lock_guard<std::mutex> lock(mutex_);
      stopping_ = true;
    }
    wake_.notify_one();
    thread_.join();
  }

private:
  using Clock = std::chrono::steady_clock;

  template<typename Send>
  void run(std::chrono::microseconds period, Send & send)
  {
    const auto tolerance = period / 2;
    // The rate limit, a policer rather than a queue: a send is allowed from half a period before
    // its turn at the average rate (`turn`). A write() that comes sooner is not answered on its
    // own (its command leaves with the next one, or with the fallback): waiting for the turn
    // instead would tie every later command to the late one's phase, a lag that never ends when
    // the controller manager runs at exactly the writer's rate.
    Clock::time_point turn = Clock::now();
    Clock::time_point last_woken = turn;  // the newest send that write() asked for
    Clock::time_point last_sent = turn;
    bool falling_back = false;            // write() is late: sending every period
    std::unique_lock<std::mutex> lock(mutex_);
    while (!stopping_) {
      const Clock::time_point due = falling_back ? last_sent + period : last_woken + 2 * period;
      wake_.wait_until(lock, due, [this]() {return woken_ || stopping_;});
      if (stopping_) {
        break;
      }
      const bool asked = woken_;
      woken_ = false;
      const Clock::time_point allowed = turn - tolerance;
      if (Clock::now() < allowed) {
        if (asked) {
          continue;  // sooner than the rate allows
        }
        // The fallback's own period met a send write() asked for: wait for the turn.
        wake_.wait_until(lock, allowed, [this]() {return stopping_;});
        if (stopping_) {
          break;
        }
      }
      lock.unlock();
      const Clock::time_point now = Clock::now();
      send();
      last_sent = now;
      if (asked) {
        last_woken = now;
      }
      falling_back = !asked;
      turn = (turn > now ? turn : now) + period;
      lock.lock();
    }
  }

  std::mutex mutex_;
  std::condition_variable wake_;
  bool woken_{false};     // mutex_: write() asked for a send
  bool stopping_{false};  // mutex_: stop() asked the thread to end
  std::thread thread_;
};

}  // namespace robot_hardware_interface

#endif  // ROBOT_HARDWARE_INTERFACE__COMMON__COMMAND_WRITER_HPP_
