// rhi-gen test stand-in (not the real ROS 2 code): rclcpp::Executor (ROS 2 Humble API subset).
//
// Semantics kept from Humble:
//  * spin() throws std::runtime_error if this executor is already spinning;
//  * cancel() only clears the "spinning" flag: a cancel() that happens *before* spin() started is
//    lost and spin() then blocks until the next cancel() (same race as the real executor -- join
//    your spin thread only after making sure spin() really stopped, or cancel in a loop);
//  * spin() also returns when rclcpp::shutdown() is called;
//  * add_node() of a node that is already in an executor throws std::runtime_error;
//    remove_node() of a node that is not in this executor throws std::runtime_error;
//  * is_spinning() (every distro, Humble since rclcpp 16.0.0) is true while inside spin()/spin_some()/
//    spin_until_future_complete();
//  * spin_until_future_complete(future, timeout) (every distro; also rclcpp::spin_until_future_complete
//    in rclcpp/executors.hpp) returns SUCCESS when the future is ready (at once if it already is),
//    TIMEOUT after `timeout` (negative: never), INTERRUPTED on cancel()/shutdown(); it throws if the
//    executor is already spinning.
//
// Fake behaviour: spin() blocks (no busy loop) until cancel()/shutdown(). Subscriptions are fed by
// the test (rhi_fake::ros::deliver, on the test's thread). Service requests and responses queued on
// the executor's nodes (rclcpp/client.hpp, rclcpp/service.hpp) run inside spin(), spin_some() and
// spin_until_future_complete(), on the spinning thread, in the order they arrived. Wall timers of the
// executor's nodes fire inside spin() only after rhi_fake::ros::set_realtime_timers(true); otherwise
// only when the test calls rhi_fake::ros::fire_timers().
#ifndef RCLCPP__EXECUTOR_HPP_
#define RCLCPP__EXECUTOR_HPP_

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <future>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

#include "rclcpp/context.hpp"
#include "rclcpp/future_return_code.hpp"
#include "rclcpp/macros.hpp"
#include "rclcpp/node.hpp"
#include "rclcpp/node_interfaces/node_base_interface.hpp"
#include "rclcpp/timer.hpp"
#include "rclcpp/utilities.hpp"
#include "rclcpp/visibility_control.hpp"
#include "rhi_fake/detail/ros_core.hpp"

namespace rclcpp
{

struct ExecutorOptions
{
  ExecutorOptions()
  : context(std::make_shared<rclcpp::Context>()) {}
  rclcpp::Context::SharedPtr context;
  size_t max_conditions = 0;
};

class Executor
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS_NOT_COPYABLE(Executor)

  explicit Executor(const rclcpp::ExecutorOptions & options = rclcpp::ExecutorOptions())
  : core_(std::make_shared<::rhi_fake::detail::ExecutorCore>())
  {
    (void)options;
    auto & reg = ::rhi_fake::detail::ros_registry();
    std::lock_guard<std::mutex> lock(reg.mutex);
    for (auto it = reg.executors.begin(); it != reg.executors.end(); ) {
      if (it->expired()) {
        it = reg.executors.erase(it);
      } else {
        ++it;
      }
    }
    reg.executors.push_back(core_);
  }

  Executor(const Executor &) = delete;
  Executor & operator=(const Executor &) = delete;

  virtual ~Executor()
  {
    std::lock_guard<std::mutex> lock(nodes_mutex_);
    for (auto & node : nodes_) {
      ::rhi_fake::detail::ExecutorCore * expected = core_.get();
      node->executor.compare_exchange_strong(expected, nullptr);
    }
    nodes_.clear();
  }

  virtual void spin() = 0;

  virtual void add_node(
    rclcpp::node_interfaces::NodeBaseInterface::SharedPtr node_ptr, bool notify = true)
  {
    (void)notify;
    const auto & node = node_ptr->rhi_core();
    ::rhi_fake::detail::ExecutorCore * expected = nullptr;
    if (!node->executor.compare_exchange_strong(expected, core_.get())) {
      throw std::runtime_error(
              std::string("Node '") + node->fqn + "' has already been added to an executor.");
    }
    std::lock_guard<std::mutex> lock(nodes_mutex_);
    nodes_.push_back(node);
  }

  virtual void add_node(std::shared_ptr<rclcpp::Node> node_ptr, bool notify = true)
  {
    this->add_node(node_ptr->get_node_base_interface(), notify);
  }

  virtual void remove_node(
    rclcpp::node_interfaces::NodeBaseInterface::SharedPtr node_ptr, bool notify = true)
  {
    (void)notify;
    const auto & node = node_ptr->rhi_core();
    ::rhi_fake::detail::ExecutorCore * expected = core_.get();
    if (!node->executor.compare_exchange_strong(expected, nullptr)) {
      throw std::runtime_error("Node needs to be associated with this executor.");
    }
    std::lock_guard<std::mutex> lock(nodes_mutex_);
    nodes_.erase(std::remove(nodes_.begin(), nodes_.end(), node), nodes_.end());
  }

  virtual void remove_node(std::shared_ptr<rclcpp::Node> node_ptr, bool notify = true)
  {
    this->remove_node(node_ptr->get_node_base_interface(), notify);
  }

  /// Fires the due timers once (real-time mode only) and returns; never blocks.
  virtual void spin_some(std::chrono::nanoseconds max_duration = std::chrono::nanoseconds(0))
  {
    (void)max_duration;
    if (core_->spinning.exchange(true)) {
      throw std::runtime_error("spin_some() called while already spinning");
    }
    struct Reset
    {
      ::rhi_fake::detail::ExecutorCore & c;
      ~Reset() {c.spinning.store(false);}
    } reset{*core_};
    run_node_work();
    if (::rhi_fake::detail::ros_registry().realtime_timers.load()) {
      fire_due_timers(rclcpp::TimerBase::steady_now_ns());
    }
  }

  /// Spin this executor's nodes until `future` is ready (SUCCESS), `timeout` passed (TIMEOUT; a
  /// negative timeout never passes) or cancel()/shutdown() (INTERRUPTED).
  template<typename FutureT, typename TimeRepT = int64_t, typename TimeT = std::milli>
  FutureReturnCode
  spin_until_future_complete(
    const FutureT & future,
    std::chrono::duration<TimeRepT, TimeT> timeout = std::chrono::duration<TimeRepT, TimeT>(-1))
  {
    if (future.wait_for(std::chrono::seconds(0)) == std::future_status::ready) {
      return FutureReturnCode::SUCCESS;
    }
    const auto timeout_ns = std::chrono::duration_cast<std::chrono::nanoseconds>(timeout);
    const auto end_time = std::chrono::steady_clock::now() +
      (timeout_ns > std::chrono::nanoseconds::zero() ? timeout_ns : std::chrono::nanoseconds::zero());
    if (core_->spinning.exchange(true)) {
      throw std::runtime_error("spin_until_future_complete() called while already spinning");
    }
    struct Reset
    {
      ::rhi_fake::detail::ExecutorCore & c;
      ~Reset() {c.spinning.store(false);}
    } reset{*core_};
    auto & reg = ::rhi_fake::detail::ros_registry();
    while (rclcpp::ok() && core_->spinning.load()) {
      std::uint64_t gen = 0;
      {
        std::lock_guard<std::mutex> lock(core_->mutex);
        gen = core_->wake_generation;
      }
      run_node_work();
      std::int64_t wait_ns = 10 * 1000 * 1000;   // also notices futures set by other threads
      if (reg.realtime_timers.load()) {
        const std::int64_t next_due = fire_due_timers(rclcpp::TimerBase::steady_now_ns());
        if (next_due != INT64_MAX) {
          wait_ns = std::max<std::int64_t>(
            0, std::min<std::int64_t>(wait_ns, next_due - rclcpp::TimerBase::steady_now_ns()));
        }
      }
      if (future.wait_for(std::chrono::seconds(0)) == std::future_status::ready) {
        return FutureReturnCode::SUCCESS;
      }
      if (timeout_ns >= std::chrono::nanoseconds::zero()) {
        const auto now = std::chrono::steady_clock::now();
        if (now >= end_time) {
          return FutureReturnCode::TIMEOUT;
        }
        wait_ns = std::min<std::int64_t>(
          wait_ns, std::chrono::duration_cast<std::chrono::nanoseconds>(end_time - now).count());
      }
      std::unique_lock<std::mutex> lock(core_->mutex);
      if (wait_ns > 0) {
        core_->cv.wait_for(
          lock, std::chrono::nanoseconds(wait_ns),
          [&] {return core_->wake_generation != gen || !core_->spinning.load();});
      }
    }
    return FutureReturnCode::INTERRUPTED;
  }

  /// Stop spin(): clears the spinning flag and wakes the spinning thread.
  void cancel()
  {
    {
      std::lock_guard<std::mutex> lock(core_->mutex);
      core_->spinning.store(false);
      core_->wake_generation++;
    }
    core_->cv.notify_all();
  }

  /// True while this executor is inside spin() / spin_some() (any thread may ask).
  bool is_spinning() {return core_->spinning.load();}

  /// Stand-in internal (used by rhi_fake::ros hooks).
  const std::shared_ptr<::rhi_fake::detail::ExecutorCore> & rhi_core() const {return core_;}

protected:
  /// Body of spin() shared by the executors.
  void rhi_spin_blocking(const char * what)
  {
    auto & reg = ::rhi_fake::detail::ros_registry();
    if (core_->spinning.exchange(true)) {
      throw std::runtime_error(std::string(what) + " called while already spinning");
    }
    reg.spin_state_cv.notify_all();
    struct Reset
    {
      ::rhi_fake::detail::ExecutorCore & c;
      ::rhi_fake::detail::RosRegistry & r;
      ~Reset()
      {
        c.spinning.store(false);
        {
          // Take the registry mutex so that hooks waiting on spin_state_cv see the change.
          std::lock_guard<std::mutex> lock(r.mutex);
        }
        r.spin_state_cv.notify_all();
      }
    } reset{*core_, reg};
    {
      std::lock_guard<std::mutex> lock(reg.mutex);
    }
    reg.spin_state_cv.notify_all();

    while (rclcpp::ok() && core_->spinning.load()) {
      std::uint64_t gen = 0;   // read before the work: a later post_work() changes it, no lost wake-up
      {
        std::lock_guard<std::mutex> lock(core_->mutex);
        gen = core_->wake_generation;
      }
      run_node_work();
      std::int64_t wait_ns = 50 * 1000 * 1000;   // re-check ok()/mode at least every 50 ms
      if (reg.realtime_timers.load()) {
        std::int64_t now = rclcpp::TimerBase::steady_now_ns();
        std::int64_t next_due = fire_due_timers(now);
        if (next_due != INT64_MAX) {
          std::int64_t until = next_due - rclcpp::TimerBase::steady_now_ns();
          wait_ns = std::max<std::int64_t>(0, std::min<std::int64_t>(wait_ns, until));
        }
      }
      std::unique_lock<std::mutex> lock(core_->mutex);
      if (!core_->spinning.load()) {
        break;
      }
      if (wait_ns > 0) {
        core_->cv.wait_for(
          lock, std::chrono::nanoseconds(wait_ns),
          [&] {return core_->wake_generation != gen || !core_->spinning.load();});
      }
    }
  }

  /// Runs the queued service requests/responses of this executor's nodes (rhi_fake/detail/ros_core.hpp).
  std::size_t run_node_work()
  {
    std::array<std::shared_ptr<::rhi_fake::detail::NodeCore>, ::rhi_fake::detail::kMaxFanout> nodes;
    std::size_t n = 0;
    {
      std::lock_guard<std::mutex> lock(nodes_mutex_);
      for (const auto & node : nodes_) {
        if (n == nodes.size()) {break;}
        nodes[n++] = node;
      }
    }
    std::size_t ran = 0;
    for (std::size_t i = 0; i < n; ++i) {
      ran += ::rhi_fake::detail::run_work(*nodes[i]);
      nodes[i].reset();
    }
    return ran;
  }

  /// Fires every due, non-canceled timer of this executor's nodes; returns the earliest next due
  /// time (steady ns) of those timers, or INT64_MAX if there are none.
  std::int64_t fire_due_timers(std::int64_t now_ns)
  {
    std::array<std::shared_ptr<rclcpp::TimerBase>, ::rhi_fake::detail::kMaxFanout> timers;
    std::size_t n = 0;
    {
      auto & reg = ::rhi_fake::detail::ros_registry();
      std::lock_guard<std::mutex> lock(reg.mutex);
      for (auto & weak : reg.timers) {
        auto t = weak.lock();
        if (t && t->rhi_node().executor.load() == core_.get() && n < timers.size()) {
          timers[n++] = std::move(t);
        }
      }
    }
    std::int64_t next = INT64_MAX;
    for (std::size_t i = 0; i < n; ++i) {
      if (!core_->spinning.load()) {break;}
      timers[i]->rhi_fire_if_due(now_ns);
      if (!timers[i]->is_canceled()) {
        next = std::min(next, timers[i]->rhi_next_due_ns());
      }
      timers[i].reset();
    }
    return next;
  }

  std::shared_ptr<::rhi_fake::detail::ExecutorCore> core_;
  std::mutex nodes_mutex_;
  std::vector<std::shared_ptr<::rhi_fake::detail::NodeCore>> nodes_;
};

}  // namespace rclcpp

#endif  // RCLCPP__EXECUTOR_HPP_
