// rhi-gen test stand-in (not the real ROS 2 code): rclcpp::TimerBase / GenericTimer / WallTimer
// (ROS 2 Humble API subset). Callback signatures: void() or void(rclcpp::TimerBase &) (anything
// else does not compile, as in rclcpp). A fake timer only fires when a test calls
// rhi_fake::ros::fire_timers(), or -- after rhi_fake::ros::set_realtime_timers(true) -- from
// inside Executor::spin() of the executor its node was added to, every period (steady clock).
// Firing holds the node's callback mutex and never allocates.
#ifndef RCLCPP__TIMER_HPP_
#define RCLCPP__TIMER_HPP_

#include <atomic>
#include <chrono>
#include <cstdint>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <tuple>
#include <type_traits>
#include <utility>

#include "rclcpp/context.hpp"
#include "rclcpp/macros.hpp"
#include "rclcpp/visibility_control.hpp"
#include "rhi_fake/detail/function_traits.hpp"
#include "rhi_fake/detail/ros_core.hpp"

namespace rclcpp
{

class TimerBase
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS_NOT_COPYABLE(TimerBase)

  virtual ~TimerBase() = default;

  /// Stop the timer from firing (until reset()).
  void cancel() {canceled_.store(true);}

  bool is_canceled() {return canceled_.load();}

  /// Restart the period from now and un-cancel.
  void reset()
  {
    next_due_ns_.store(steady_now_ns() + period_.count());
    canceled_.store(false);
  }

  /// Run the user callback once, on the calling thread.
  virtual void execute_callback() = 0;

  virtual bool is_steady() = 0;

  std::chrono::nanoseconds time_until_trigger()
  {
    return std::chrono::nanoseconds(next_due_ns_.load() - steady_now_ns());
  }

  bool is_ready() {return !canceled_.load() && steady_now_ns() >= next_due_ns_.load();}

  // ---- stand-in internals (used by the fake executor and rhi_fake::ros hooks) ----
  std::chrono::nanoseconds rhi_period() const {return period_;}
  std::int64_t rhi_next_due_ns() const {return next_due_ns_.load();}
  ::rhi_fake::detail::NodeCore & rhi_node() const {return *node_;}

  /// Fire once now (under the node's callback mutex) unless canceled; returns true if it ran.
  bool rhi_fire()
  {
    std::lock_guard<std::recursive_mutex> lock(node_->callback_mutex);
    if (canceled_.load()) {
      return false;
    }
    advance_due(steady_now_ns());
    execute_callback();
    return true;
  }

  /// Fire if the period elapsed (real-time mode).
  bool rhi_fire_if_due(std::int64_t now_ns)
  {
    std::lock_guard<std::recursive_mutex> lock(node_->callback_mutex);
    if (canceled_.load() || now_ns < next_due_ns_.load()) {
      return false;
    }
    advance_due(now_ns);
    execute_callback();
    return true;
  }

  static std::int64_t steady_now_ns()
  {
    return std::chrono::duration_cast<std::chrono::nanoseconds>(
      std::chrono::steady_clock::now().time_since_epoch()).count();
  }

protected:
  TimerBase(std::chrono::nanoseconds period, std::shared_ptr<::rhi_fake::detail::NodeCore> node)
  : period_(period), node_(std::move(node))
  {
    if (period.count() < 0) {
      throw std::invalid_argument("timer period cannot be negative");
    }
    next_due_ns_.store(steady_now_ns() + period_.count());
  }

private:
  // rcl_timer_call semantics: next = previous + period; if that is already in the past, skip
  // to the next period boundary after now.
  void advance_due(std::int64_t now_ns)
  {
    std::int64_t p = period_.count();
    std::int64_t next = next_due_ns_.load() + p;
    if (next < now_ns) {
      next = (p == 0) ? now_ns : next + ((now_ns - next) / p + 1) * p;
    }
    next_due_ns_.store(next);
  }

  std::chrono::nanoseconds period_;
  std::shared_ptr<::rhi_fake::detail::NodeCore> node_;
  std::atomic<bool> canceled_{false};
  std::atomic<std::int64_t> next_due_ns_{0};
};

}  // namespace rclcpp

namespace rhi_fake {
namespace detail {
template<typename FunctorT>
struct timer_callback_ok
{
  using traits = ft::of<FunctorT>;
  static constexpr bool value_impl()
  {
    if constexpr (traits::arity == 0) {
      return true;
    } else if constexpr (traits::arity == 1) {
      return std::is_same<std::tuple_element_t<0, typename traits::arguments>, rclcpp::TimerBase &>::value;
    } else {
      return false;
    }
  }
  static constexpr bool value = value_impl();
};
}  // namespace detail
}  // namespace rhi_fake

namespace rclcpp
{

template<
  typename FunctorT,
  typename std::enable_if<::rhi_fake::detail::timer_callback_ok<FunctorT>::value>::type * = nullptr>
class GenericTimer : public TimerBase
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(GenericTimer)

  /// Stand-in internal constructor (timers are made by Node::create_wall_timer).
  GenericTimer(
    std::chrono::nanoseconds period, FunctorT && callback,
    std::shared_ptr<::rhi_fake::detail::NodeCore> node)
  : TimerBase(period, std::move(node)), callback_(std::forward<FunctorT>(callback)) {}

  virtual ~GenericTimer() = default;

  void execute_callback() override
  {
    if constexpr (::rhi_fake::detail::ft::of<FunctorT>::arity == 0) {
      callback_();
    } else {
      callback_(*this);
    }
  }

  bool is_steady() override {return true;}

protected:
  FunctorT callback_;
};

template<
  typename FunctorT,
  typename std::enable_if<::rhi_fake::detail::timer_callback_ok<FunctorT>::value>::type * = nullptr>
class WallTimer : public GenericTimer<FunctorT>
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(WallTimer)

  WallTimer(
    std::chrono::nanoseconds period, FunctorT && callback,
    std::shared_ptr<::rhi_fake::detail::NodeCore> node)
  : GenericTimer<FunctorT>(period, std::forward<FunctorT>(callback), std::move(node)) {}

  bool is_steady() override {return true;}
};

}  // namespace rclcpp

#endif  // RCLCPP__TIMER_HPP_
