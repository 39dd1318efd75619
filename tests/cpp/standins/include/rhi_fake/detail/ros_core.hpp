// rhi-gen test stand-in (not the real ROS 2 code). Process-wide state of the fake rclcpp:
// init/shutdown, topics (publishers, subscriptions, last published message), wall timers and
// executors. Everything is guarded by RosRegistry::mutex; the per-message hot paths (publish,
// deliver, timer firing) take only short locks and never allocate once warmed up.
#pragma once

#include <array>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <string_view>
#include <typeindex>
#include <typeinfo>
#include <vector>

namespace rclcpp
{
class PublisherBase;
class SubscriptionBase;
class TimerBase;
}  // namespace rclcpp

namespace rhi_fake {
namespace detail {

/// Maximum number of live subscriptions / timers one delivery or firing round reaches.
constexpr std::size_t kMaxFanout = 64;

/// QoS as requested by the driver (values of the rmw_qos_*_policy_t enums).
struct QosSnapshot
{
  int history = 0;
  std::size_t depth = 0;
  int reliability = 0;
  int durability = 0;
};

struct ExecutorCore;

/// Shared state of one rclcpp::Node (kept alive by its entities).
struct NodeCore
{
  std::string name;
  std::string ns;
  std::string fqn;
  /// Held while any callback of this node runs: the node's default callback group is mutually
  /// exclusive, so a node's subscription and timer callbacks never overlap (as with rclcpp).
  std::recursive_mutex callback_mutex;
  /// Executor this node was added to (nullptr: none).
  std::atomic<ExecutorCore *> executor{nullptr};
};

/// Last message published on a topic (type-erased base).
struct TopicSlotBase
{
  TopicSlotBase(std::type_index t, const char * n)
  : type(t), type_name(n) {}
  virtual ~TopicSlotBase() = default;

  const std::type_index type;
  const char * const type_name;
  std::mutex mutex;
  std::uint64_t count = 0;   // under mutex
  bool has_value = false;    // under mutex
};

template<typename MessageT>
struct TopicSlot : TopicSlotBase
{
  TopicSlot(std::type_index t, const char * n)
  : TopicSlotBase(t, n) {}
  MessageT last{};   // copy-assigned on every publish (no allocation once capacities are warm)
};

struct EndpointEntry
{
  std::weak_ptr<void> owner;          // PublisherBase / SubscriptionBase (weak)
  QosSnapshot qos;
  std::string node;
  std::type_index type;
  const char * type_name;
};

struct TopicRecord
{
  std::shared_ptr<TopicSlotBase> slot;     // created by the first publisher
  std::vector<EndpointEntry> publishers;
  std::vector<EndpointEntry> subscriptions;
};

struct ExecutorCore
{
  std::mutex mutex;
  std::condition_variable cv;
  std::atomic<bool> spinning{false};
  std::uint64_t wake_generation = 0;   // under mutex; bumped by cancel/shutdown/mode changes
};

struct RosRegistry
{
  std::mutex mutex;
  std::condition_variable spin_state_cv;   // notified when an executor starts/stops spinning
  std::atomic<bool> initialized{false};    // rclcpp::init() called and not shut down
  std::uint64_t init_count = 0;
  std::map<std::string, TopicRecord, std::less<>> topics;
  std::vector<std::weak_ptr<rclcpp::TimerBase>> timers;
  std::vector<std::weak_ptr<ExecutorCore>> executors;
  std::atomic<bool> realtime_timers{false};
};

inline RosRegistry & ros_registry()
{
  static RosRegistry registry;
  return registry;
}

/// Wake every executor's wait (cancel, shutdown, real-time mode change).
inline void wake_all_executors()
{
  std::vector<std::shared_ptr<ExecutorCore>> cores;
  {
    RosRegistry & reg = ros_registry();
    std::lock_guard<std::mutex> lock(reg.mutex);
    for (auto & weak : reg.executors) {
      if (auto core = weak.lock()) {cores.push_back(core);}
    }
  }
  for (auto & core : cores) {
    {
      std::lock_guard<std::mutex> lock(core->mutex);
      core->wake_generation++;
    }
    core->cv.notify_all();
  }
}

/// Topic name as used for hook look-ups: an absolute name is used as is, a relative one gets a
/// leading '/'. Uses `buffer` for the relative case so nothing is allocated.
inline std::string_view hook_topic_key(std::string_view name, char (&buffer)[512])
{
  if (!name.empty() && name.front() == '/') {
    return name;
  }
  if (name.size() + 1 >= sizeof(buffer)) {
    throw std::length_error("rhi_fake: topic name too long");
  }
  buffer[0] = '/';
  std::memcpy(buffer + 1, name.data(), name.size());
  return std::string_view(buffer, name.size() + 1);
}

template<typename Vec>
inline void prune_dead(Vec & entries)
{
  for (auto it = entries.begin(); it != entries.end(); ) {
    if (it->owner.expired()) {
      it = entries.erase(it);
    } else {
      ++it;
    }
  }
}

}  // namespace detail
}  // namespace rhi_fake
