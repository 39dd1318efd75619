// rhi-gen test stand-in (not the real ROS 2 code). Process-wide state of the fake rclcpp:
// init/shutdown, topics (publishers, subscriptions, last published message), services (servers,
// clients, the test's fake servers, the requests sent), wall timers and executors. Everything is
// guarded by RosRegistry::mutex; the per-message hot paths (publish, deliver, timer firing) take
// only short locks and never allocate once warmed up. Service requests and responses are queued on
// the receiving node (NodeCore::work) and run when an executor spins that node.
#pragma once

#include <array>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <deque>
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
class ClientBase;
class ServiceBase;
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
  /// Service requests for this node's services and responses for its clients, oldest first: an
  /// executor spinning this node runs them (under callback_mutex), as rclcpp takes them from rmw.
  std::mutex work_mutex;
  std::deque<std::function<void()>> work;   // under work_mutex
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
  // Called with the message after each publish, under mutex (rhi_fake::ros::observe_publishes).
  std::function<void(const void *)> observer;
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

/// What a client is to the registry: where the responses to its requests go.
class ResponseSink
{
public:
  virtual ~ResponseSink() = default;
  virtual std::shared_ptr<NodeCore> rhi_sink_node() const = 0;
  /// Runs on the thread spinning rhi_sink_node(), under its callback mutex.
  virtual void rhi_take_response(std::int64_t sequence_number, std::shared_ptr<void> response) = 0;
};

/// What a service server is to the registry: where the requests for its name go.
class RequestSink
{
public:
  virtual ~RequestSink() = default;
  virtual std::shared_ptr<NodeCore> rhi_sink_node() const = 0;
  /// Runs on the thread spinning rhi_sink_node(), under its callback mutex.
  virtual void rhi_take_request(
    std::uint64_t client_id, std::int64_t sequence_number, std::shared_ptr<void> request) = 0;
};

/// The server the test plays for a service name (rhi_fake/services.hpp).
struct FakeServer
{
  enum class Mode {Answer, Hold};
  Mode mode = Mode::Answer;
  std::type_index type{typeid(void)};   // ServiceT (Answer); typeid(void): any type (Hold)
  const char * type_name = "";
  /// Answer mode: makes the response (a shared_ptr<ServiceT::Response>) from the request.
  std::function<std::shared_ptr<void>(const void * request)> answer;
};

/// A request the test's server holds (Hold mode): where its response must go.
struct HeldRequest
{
  std::uint64_t client_id;
  std::int64_t sequence_number;
  std::type_index type;
};

struct ServiceRecord
{
  std::vector<EndpointEntry> servers;   // owner: rclcpp::ServiceBase
  std::vector<EndpointEntry> clients;   // owner: rclcpp::ClientBase
  std::shared_ptr<FakeServer> fake;      // set by the test, or null
  std::vector<HeldRequest> held;         // Hold mode
  // every request sent to this name, oldest first (copies of ServiceT::Request)
  std::vector<std::pair<std::type_index, std::shared_ptr<const void>>> requests;
  std::uint64_t calls = 0;
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
  std::map<std::string, ServiceRecord, std::less<>> services;
  /// Clients by the id written into their requests' rmw_request_id_t::writer_guid (responses are
  /// routed back through it, also those a deferred service callback sends later).
  std::map<std::uint64_t, std::weak_ptr<ResponseSink>> clients_by_id;
  std::uint64_t next_client_id = 1;
  std::condition_variable graph_cv;        // notified when a server (real or fake) appears
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

/// Queue `fn` on `node` (a service request or response) and wake the executors: the one spinning
/// `node` runs it. Call without holding the registry mutex.
inline void post_work(const std::shared_ptr<NodeCore> & node, std::function<void()> fn)
{
  {
    std::lock_guard<std::mutex> lock(node->work_mutex);
    node->work.push_back(std::move(fn));
  }
  wake_all_executors();
}

/// Queue the response to request `sequence_number` of client `client_id` on the client's node (it
/// completes the client's future when that node is spun). False if the client no longer exists.
inline bool route_response(
  std::uint64_t client_id, std::int64_t sequence_number, std::shared_ptr<void> response)
{
  std::shared_ptr<ResponseSink> client;   // released outside the registry lock (it may be the last owner)
  {
    RosRegistry & reg = ros_registry();
    std::lock_guard<std::mutex> lock(reg.mutex);
    auto it = reg.clients_by_id.find(client_id);
    if (it != reg.clients_by_id.end()) {
      client = it->second.lock();
    }
  }
  if (!client) {
    return false;
  }
  std::weak_ptr<ResponseSink> weak = client;
  post_work(
    client->rhi_sink_node(),
    [weak, sequence_number, response = std::move(response)]() {
      if (auto c = weak.lock()) {
        c->rhi_take_response(sequence_number, response);
      }
    });
  return true;
}

/// Queue a request on a server's node (its callback runs when that node is spun).
inline void post_request(
  const std::shared_ptr<RequestSink> & server, std::uint64_t client_id,
  std::int64_t sequence_number, std::shared_ptr<void> request)
{
  std::weak_ptr<RequestSink> weak = server;
  post_work(
    server->rhi_sink_node(),
    [weak, client_id, sequence_number, request = std::move(request)]() {
      if (auto s = weak.lock()) {
        s->rhi_take_request(client_id, sequence_number, request);
      }
    });
}

/// Run the queued work of `node` on this thread, under its callback mutex; returns how many ran.
inline std::size_t run_work(NodeCore & node)
{
  std::size_t ran = 0;
  while (true) {
    std::function<void()> fn;
    {
      std::lock_guard<std::mutex> lock(node.work_mutex);
      if (node.work.empty()) {
        return ran;
      }
      fn = std::move(node.work.front());
      node.work.pop_front();
    }
    std::lock_guard<std::recursive_mutex> lock(node.callback_mutex);
    fn();
    ++ran;
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
