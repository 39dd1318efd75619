// rhi-gen test stand-in (not the real unitree_sdk2): unitree::common::RecurrentThread and
// CreateRecurrentThread / CreateRecurrentThreadEx (same signatures as the SDK:
// CreateRecurrentThreadEx(name, cpuId, intervalMicrosec, func, args...) binds func(args...)).
//
// Stopping: as in the SDK, call Wait() on the returned ThreadPtr (it is virtual) -- that stops the
// loop and waits for the running iteration. The fake's destructor also stops and joins (the SDK's
// destructor lives in the closed-source library and was not verified; do not rely on it).
//
// Fake modes (chosen when the thread is created, see rhi_fake/unitree.hpp):
//  * ticked (default): nothing runs by itself; rhi_fake::unitree::tick_thread(name) runs the
//    function once on the test's thread;
//  * real (rhi_fake::unitree::use_real_threads(true)): a std::thread runs the function every
//    intervalMicrosec (0 = back to back) until Wait() / destruction.
#ifndef __UT_RECURRENT_THREAD_HPP__
#define __UT_RECURRENT_THREAD_HPP__

#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <utility>

#include <unitree/common/thread/thread.hpp>
#include "rhi_fake/detail/unitree_core.hpp"

#define UT_THREAD_TIME_INTERVAL_MICROSEC 1000000

namespace unitree
{
namespace common
{
class RecurrentThread : public Thread
{
public:
  __UT_THREAD_DECL_TMPL_FUNC_ARG__
  explicit RecurrentThread(uint64_t intervalMicrosec, __UT_THREAD_TMPL_FUNC_ARG__)
  : Thread()
  {
    Start(std::string(), UT_CPU_ID_NONE, intervalMicrosec, std::bind(__UT_THREAD_BIND_FUNC_ARG__));
  }

  __UT_THREAD_DECL_TMPL_FUNC_ARG__
  explicit RecurrentThread(
    const std::string & name, int32_t cpuId, uint64_t intervalMicrosec,
    __UT_THREAD_TMPL_FUNC_ARG__)
  : Thread(name, cpuId)
  {
    Start(name, cpuId, intervalMicrosec, std::bind(__UT_THREAD_BIND_FUNC_ARG__));
  }

  RecurrentThread(const RecurrentThread &) = delete;
  RecurrentThread & operator=(const RecurrentThread &) = delete;

  virtual ~RecurrentThread()
  {
    Stop(0, true);
  }

  /// Stop the loop and wait for it (microsec == 0: no limit). True when the thread has finished.
  bool Wait(int64_t microsec = 0) override
  {
    return Stop(microsec, false);
  }

private:
  void Start(const std::string & name, int32_t cpuId, uint64_t intervalMicrosec, std::function<void()> fn)
  {
    core_ = std::make_shared<::rhi_fake::detail::ThreadCore>();
    core_->name = name;
    core_->cpu_id = cpuId;
    core_->interval_us = intervalMicrosec;
    core_->fn = std::move(fn);
    auto & reg = ::rhi_fake::detail::unitree_registry();
    core_->real = reg.real_threads.load();
    {
      std::lock_guard<std::mutex> lock(reg.mutex);
      for (auto it = reg.threads.begin(); it != reg.threads.end(); ) {
        if (it->expired()) {
          it = reg.threads.erase(it);
        } else {
          ++it;
        }
      }
      reg.threads.push_back(core_);
    }
    if (core_->real) {
      ::rhi_fake::detail::ThreadCore * core = core_.get();
      core_->thread = std::thread([core]() {Loop(*core);});
    }
  }

  static void Loop(::rhi_fake::detail::ThreadCore & core)
  {
    using clock = std::chrono::steady_clock;
    const auto interval = std::chrono::microseconds(core.interval_us);
    auto next = clock::now();
    while (true) {
      {
        std::lock_guard<std::mutex> lock(core.wait_mutex);
        if (core.quit) {break;}
      }
      core.fn();
      core.runs.fetch_add(1);
      if (core.interval_us == 0) {
        std::this_thread::yield();
        continue;
      }
      next += interval;
      auto now = clock::now();
      if (next < now - interval) {next = now;}   // fell far behind: do not burst
      std::unique_lock<std::mutex> lock(core.wait_mutex);
      core.wait_cv.wait_until(lock, next, [&core] {return core.quit;});
      if (core.quit) {break;}
    }
    {
      std::lock_guard<std::mutex> lock(core.wait_mutex);
      core.finished = true;
    }
    core.wait_cv.notify_all();
  }

  bool Stop(int64_t microsec, bool destructing)
  {
    if (!core_) {return true;}
    ::rhi_fake::detail::ThreadCore & core = *core_;
    core.stopped.store(true);
    if (!core.real) {
      // wait for a tick in progress; later ticks see `stopped`
      std::lock_guard<std::recursive_mutex> lock(core.run_mutex);
      return true;
    }
    {
      std::lock_guard<std::mutex> lock(core.wait_mutex);
      core.quit = true;
    }
    core.wait_cv.notify_all();
    std::lock_guard<std::mutex> join_lock(core.join_mutex);
    if (!core.thread.joinable()) {return true;}
    if (core.thread.get_id() == std::this_thread::get_id()) {
      // stopped from inside its own function: cannot join itself
      if (destructing) {core.thread.detach();}
      return false;
    }
    if (microsec > 0) {
      std::unique_lock<std::mutex> lock(core.wait_mutex);
      if (!core.wait_cv.wait_for(
          lock, std::chrono::microseconds(microsec), [&core] {return core.finished;}))
      {
        if (!destructing) {return false;}
      }
    }
    core.thread.join();
    return true;
  }

  std::shared_ptr<::rhi_fake::detail::ThreadCore> core_;
};

typedef std::shared_ptr<RecurrentThread> RecurrentThreadPtr;

__UT_THREAD_DECL_TMPL_FUNC_ARG__
ThreadPtr CreateRecurrentThread(uint64_t intervalMicrosec, __UT_THREAD_TMPL_FUNC_ARG__)
{
  return ThreadPtr(new RecurrentThread(intervalMicrosec, __UT_THREAD_BIND_FUNC_ARG__));
}

__UT_THREAD_DECL_TMPL_FUNC_ARG__
ThreadPtr CreateRecurrentThreadEx(
  const std::string & name, int32_t cpuId, uint64_t intervalMicrosec,
  __UT_THREAD_TMPL_FUNC_ARG__)
{
  return ThreadPtr(new RecurrentThread(name, cpuId, intervalMicrosec, __UT_THREAD_BIND_FUNC_ARG__));
}

}  // namespace common
}  // namespace unitree

#endif  // __UT_RECURRENT_THREAD_HPP__
