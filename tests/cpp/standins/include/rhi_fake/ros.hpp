// rhi-gen test hooks for the fake rclcpp (test code only; generated drivers never include this).
// All functions are thread-safe. Topic arguments: absolute ("/hardware/joint_state") or relative
// ("hardware/joint_state" = "/hardware/joint_state"); drivers' names are expanded by the Node.
// See tests/cpp/standins/README.md for the full contract.
#pragma once

#include <algorithm>
#include <array>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <typeindex>
#include <vector>

#include "rclcpp/rclcpp.hpp"
#include "rhi_fake/detail/ros_core.hpp"
#include "rhi_fake/detail/time_core.hpp"

namespace rhi_fake {
namespace ros {

// ------------------------------------------------------------------ messages in / out

namespace detail_ {

template<typename MessageT>
std::size_t deliver_impl(
  std::string_view topic, const MessageT & msg, const std::shared_ptr<const MessageT> * owned)
{
  char buffer[512];
  const std::string_view key = ::rhi_fake::detail::hook_topic_key(topic, buffer);
  std::array<std::shared_ptr<rclcpp::SubscriptionBase>, ::rhi_fake::detail::kMaxFanout> subs;
  std::size_t n = 0;
  {
    auto & reg = ::rhi_fake::detail::ros_registry();
    std::lock_guard<std::mutex> lock(reg.mutex);
    auto it = reg.topics.find(key);
    if (it == reg.topics.end()) {
      return 0;
    }
    for (auto & entry : it->second.subscriptions) {
      if (entry.type != std::type_index(typeid(MessageT))) {continue;}
      auto sp = std::static_pointer_cast<rclcpp::SubscriptionBase>(entry.owner.lock());
      if (!sp) {continue;}
      if (n == subs.size()) {
        throw std::length_error("rhi_fake: too many subscriptions on one topic");
      }
      subs[n++] = std::move(sp);
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    subs[i]->rhi_deliver_erased(static_cast<const void *>(&msg), static_cast<const void *>(owned));
    subs[i].reset();
  }
  return n;
}

}  // namespace detail_

/// Run the callback of every live subscription of type MessageT on `topic`, now, on this thread.
/// Returns the number of subscriptions reached (0 if none). Never allocates for const-ref
/// callbacks; see rclcpp/subscription.hpp for the other callback kinds.
template<typename MessageT>
std::size_t deliver(std::string_view topic, const MessageT & msg)
{
  return detail_::deliver_impl<MessageT>(topic, msg, nullptr);
}

/// Same, handing `msg` itself to shared_ptr<const MessageT> callbacks (no copy, no allocation).
template<typename MessageT>
std::size_t deliver(std::string_view topic, const std::shared_ptr<const MessageT> & msg)
{
  if (!msg) {throw std::invalid_argument("rhi_fake::ros::deliver: null message");}
  return detail_::deliver_impl<MessageT>(topic, *msg, &msg);
}

template<typename MessageT>
std::size_t deliver(std::string_view topic, const std::shared_ptr<MessageT> & msg)
{
  std::shared_ptr<const MessageT> c = msg;
  return deliver<MessageT>(topic, c);
}

namespace detail_ {
template<typename MessageT>
std::shared_ptr<::rhi_fake::detail::TopicSlot<MessageT>> slot_of(std::string_view topic)
{
  char buffer[512];
  const std::string_view key = ::rhi_fake::detail::hook_topic_key(topic, buffer);
  auto & reg = ::rhi_fake::detail::ros_registry();
  std::lock_guard<std::mutex> lock(reg.mutex);
  auto it = reg.topics.find(key);
  if (it == reg.topics.end() || !it->second.slot) {
    return nullptr;
  }
  if (it->second.slot->type != std::type_index(typeid(MessageT))) {
    throw std::logic_error(
            "rhi_fake: topic '" + std::string(key) + "' carries " + it->second.slot->type_name);
  }
  return std::static_pointer_cast<::rhi_fake::detail::TopicSlot<MessageT>>(it->second.slot);
}
}  // namespace detail_

/// Copy of the last message published on `topic` into `out`; false if nothing was published yet.
/// Throws std::logic_error if the topic's publishers use another message type.
template<typename MessageT>
bool last_published(std::string_view topic, MessageT & out)
{
  auto slot = detail_::slot_of<MessageT>(topic);
  if (!slot) {return false;}
  std::lock_guard<std::mutex> lock(slot->mutex);
  if (!slot->has_value) {return false;}
  out = slot->last;
  return true;
}

template<typename MessageT>
std::optional<MessageT> last_published(std::string_view topic)
{
  MessageT out;
  if (!last_published<MessageT>(topic, out)) {return std::nullopt;}
  return out;
}

namespace detail_ {
/// The slot of `topic`'s published messages, null before a publisher created the topic.
inline std::shared_ptr<::rhi_fake::detail::TopicSlotBase> published_slot(std::string_view topic)
{
  char buffer[512];
  const std::string_view key = ::rhi_fake::detail::hook_topic_key(topic, buffer);
  auto & reg = ::rhi_fake::detail::ros_registry();
  std::lock_guard<std::mutex> lock(reg.mutex);
  auto it = reg.topics.find(key);
  return it == reg.topics.end() ? nullptr : it->second.slot;
}
}  // namespace detail_

/// Call `observer` with every message published on `topic` from now on (as `const void*`, on the
/// publishing thread, under the topic's lock: it must not publish on the topic); an empty function
/// stops observing. False when no publisher has created the topic yet. The call allocates nothing.
inline bool observe_publishes(std::string_view topic, std::function<void(const void *)> observer)
{
  const auto slot = detail_::published_slot(topic);
  if (!slot) {return false;}
  std::lock_guard<std::mutex> lock(slot->mutex);
  slot->observer = std::move(observer);
  return true;
}

/// Number of publish() calls on `topic` (all publishers together) since the topic appeared.
inline std::uint64_t publish_count(std::string_view topic)
{
  const auto slot = detail_::published_slot(topic);
  if (!slot) {return 0;}
  std::lock_guard<std::mutex> lock(slot->mutex);
  return slot->count;
}

// ------------------------------------------------------------------ graph / QoS

struct EndpointInfo
{
  std::string node;                        // fully qualified node name, e.g. "/g1_hardware_interface"
  std::string type_name;                   // e.g. "sensor_msgs/msg/Imu"
  rclcpp::ReliabilityPolicy reliability;   // as requested by the driver
  rclcpp::DurabilityPolicy durability;
  rclcpp::HistoryPolicy history;
  std::size_t depth;
};

struct TopicInfo
{
  std::string name;                        // fully qualified, e.g. "/hardware/joint_command"
  std::vector<EndpointInfo> publishers;    // live ones only
  std::vector<EndpointInfo> subscriptions; // live ones only
  std::uint64_t publish_count;
};

namespace detail_ {
inline EndpointInfo to_info(const ::rhi_fake::detail::EndpointEntry & e)
{
  return EndpointInfo{
    e.node, e.type_name,
    static_cast<rclcpp::ReliabilityPolicy>(e.qos.reliability),
    static_cast<rclcpp::DurabilityPolicy>(e.qos.durability),
    static_cast<rclcpp::HistoryPolicy>(e.qos.history),
    e.qos.depth};
}
}  // namespace detail_

/// Every topic that has (or had) a publisher or subscription, sorted by name.
inline std::vector<TopicInfo> topics()
{
  std::vector<TopicInfo> out;
  std::vector<std::shared_ptr<::rhi_fake::detail::TopicSlotBase>> slots;
  {
    auto & reg = ::rhi_fake::detail::ros_registry();
    std::lock_guard<std::mutex> lock(reg.mutex);
    for (const auto & [name, record] : reg.topics) {
      TopicInfo info{name, {}, {}, 0};
      for (const auto & e : record.publishers) {
        if (!e.owner.expired()) {info.publishers.push_back(detail_::to_info(e));}
      }
      for (const auto & e : record.subscriptions) {
        if (!e.owner.expired()) {info.subscriptions.push_back(detail_::to_info(e));}
      }
      out.push_back(std::move(info));
      slots.push_back(record.slot);
    }
  }
  for (std::size_t i = 0; i < out.size(); ++i) {
    if (slots[i]) {
      std::lock_guard<std::mutex> lock(slots[i]->mutex);
      out[i].publish_count = slots[i]->count;
    }
  }
  return out;
}

/// One topic, if known.
inline std::optional<TopicInfo> topic(std::string_view name)
{
  char buffer[512];
  const std::string key(::rhi_fake::detail::hook_topic_key(name, buffer));
  for (auto & t : topics()) {
    if (t.name == key) {return t;}
  }
  return std::nullopt;
}

inline const char * to_string(rclcpp::ReliabilityPolicy p)
{
  switch (p) {
    case rclcpp::ReliabilityPolicy::BestEffort: return "best_effort";
    case rclcpp::ReliabilityPolicy::Reliable: return "reliable";
    case rclcpp::ReliabilityPolicy::SystemDefault: return "system_default";
    default: return "unknown";
  }
}

inline const char * to_string(rclcpp::DurabilityPolicy p)
{
  switch (p) {
    case rclcpp::DurabilityPolicy::Volatile: return "volatile";
    case rclcpp::DurabilityPolicy::TransientLocal: return "transient_local";
    case rclcpp::DurabilityPolicy::SystemDefault: return "system_default";
    default: return "unknown";
  }
}

inline const char * to_string(rclcpp::HistoryPolicy p)
{
  switch (p) {
    case rclcpp::HistoryPolicy::KeepLast: return "keep_last";
    case rclcpp::HistoryPolicy::KeepAll: return "keep_all";
    case rclcpp::HistoryPolicy::SystemDefault: return "system_default";
    default: return "unknown";
  }
}

// ------------------------------------------------------------------ timers

/// Fire every live, non-canceled wall timer once, now, on this thread (each under its node's
/// callback mutex), whatever executor its node is in. Returns how many ran. Never allocates.
inline std::size_t fire_timers()
{
  std::array<std::shared_ptr<rclcpp::TimerBase>, ::rhi_fake::detail::kMaxFanout> timers;
  std::size_t n = 0;
  {
    auto & reg = ::rhi_fake::detail::ros_registry();
    std::lock_guard<std::mutex> lock(reg.mutex);
    for (auto & weak : reg.timers) {
      auto t = weak.lock();
      if (!t) {continue;}
      if (n == timers.size()) {throw std::length_error("rhi_fake: too many timers");}
      timers[n++] = std::move(t);
    }
  }
  std::size_t fired = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (timers[i]->rhi_fire()) {++fired;}
    timers[i].reset();
  }
  return fired;
}

/// Periods of the live, non-canceled wall timers (creation order).
inline std::vector<std::chrono::nanoseconds> timer_periods()
{
  std::vector<std::shared_ptr<rclcpp::TimerBase>> live;
  {
    auto & reg = ::rhi_fake::detail::ros_registry();
    std::lock_guard<std::mutex> lock(reg.mutex);
    for (auto & weak : reg.timers) {
      if (auto t = weak.lock()) {live.push_back(t);}
    }
  }
  std::vector<std::chrono::nanoseconds> out;
  for (auto & t : live) {
    if (!t->is_canceled()) {out.push_back(t->rhi_period());}
  }
  return out;
}

/// When on, Executor::spin() fires the due wall timers of its nodes every period (steady clock),
/// on the spinning thread. Off by default. Takes effect immediately for running spins.
inline void set_realtime_timers(bool on)
{
  ::rhi_fake::detail::ros_registry().realtime_timers.store(on);
  ::rhi_fake::detail::wake_all_executors();
}

inline bool realtime_timers()
{
  return ::rhi_fake::detail::ros_registry().realtime_timers.load();
}

// ------------------------------------------------------------------ executors

/// True while `executor` is inside spin() / spin_some() (and not cancelled).
inline bool is_spinning(const rclcpp::Executor & executor)
{
  return executor.rhi_core()->spinning.load();
}

/// Number of executors currently inside spin().
inline std::size_t spinning_executors()
{
  auto & reg = ::rhi_fake::detail::ros_registry();
  std::lock_guard<std::mutex> lock(reg.mutex);
  std::size_t n = 0;
  for (auto & weak : reg.executors) {
    if (auto core = weak.lock()) {
      if (core->spinning.load()) {++n;}
    }
  }
  return n;
}

/// Wait until exactly `count` executors are spinning (e.g. 1 after on_activate, 0 after
/// on_deactivate). Returns false on timeout.
inline bool wait_spinning_executors(std::size_t count, std::chrono::milliseconds timeout)
{
  auto deadline = std::chrono::steady_clock::now() + timeout;
  while (true) {
    if (spinning_executors() == count) {return true;}
    if (std::chrono::steady_clock::now() >= deadline) {return false;}
    auto & reg = ::rhi_fake::detail::ros_registry();
    std::unique_lock<std::mutex> lock(reg.mutex);
    reg.spin_state_cv.wait_for(lock, std::chrono::milliseconds(2));
  }
}

// ------------------------------------------------------------------ time

/// Make every rclcpp::Clock::now() (node->now(), node->get_clock()->now(), RCLCPP_*_THROTTLE)
/// return `nanoseconds` until use_system_time(). Wall timers keep using the steady clock.
inline void set_time(std::int64_t nanoseconds)
{
  auto & core = ::rhi_fake::detail::time_core();
  core.fake_ns.store(nanoseconds);
  core.fake.store(true);
}

inline void advance_time(std::chrono::nanoseconds delta)
{
  auto & core = ::rhi_fake::detail::time_core();
  core.fake_ns.fetch_add(delta.count());
}

inline void use_system_time()
{
  ::rhi_fake::detail::time_core().fake.store(false);
}

// ------------------------------------------------------------------ reset

/// Forget topics, services (and the test's servers: rhi_fake/services.hpp), timers and executors,
/// switch real-time timers off, go back to system time and
/// un-initialize rclcpp (spinning executors return). Call only when no driver is alive.
inline void reset()
{
  rclcpp::shutdown();
  auto & reg = ::rhi_fake::detail::ros_registry();
  std::map<std::string, ::rhi_fake::detail::ServiceRecord, std::less<>> services;   // freed unlocked
  {
    std::lock_guard<std::mutex> lock(reg.mutex);
    reg.topics.clear();
    reg.timers.clear();
    reg.executors.clear();
    reg.realtime_timers.store(false);
    services.swap(reg.services);
    reg.clients_by_id.clear();
  }
  use_system_time();
}

}  // namespace ros
}  // namespace rhi_fake
