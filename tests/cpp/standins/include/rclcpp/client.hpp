// rhi-gen test stand-in (not the real ROS 2 code): rclcpp::ClientBase / rclcpp::Client<ServiceT>,
// the API of rclcpp 16 (Humble), 28 (Jazzy) and 29+ (Kilted, Rolling), which is the same but for
// the implicit conversions of the returned futures (see FutureAndRequestId below).
//
//   auto client = node->create_client<ServiceT>("name");          // rclcpp/node.hpp (per distro QoS)
//   client->wait_for_service(1s);  client->service_is_ready();
//   auto result = client->async_send_request(request);            // FutureAndRequestId
//   result.future  (std::future<SharedResponse>), result.request_id, result.share() (SharedFuture)
//   client->async_send_request(request, [](Client::SharedFuture f) {...});      // callback forms:
//   client->async_send_request(request, [](Client::SharedFutureWithRequest f) {...});
//       the callback must take exactly that parameter type (by value), as rclcpp's
//       function_traits::same_arguments requires; anything else matches no overload.
//   remove_pending_request(id | future), prune_pending_requests(), prune_requests_older_than(t)
//
// Fake transport (rhi_fake/detail/ros_core.hpp): a request is copied and queued on the node of the
// in-process server of that name and type (or answered by the server the test plays,
// rhi_fake/services.hpp); the server's callback runs when an executor spins the server's node. The
// response is queued on the client's node: the future is set, or the callback runs, when an executor
// spins the *client's* node -- a client whose node nobody spins never gets its response, as in rclcpp.
// service_is_ready() is true while a live server (or the test's) of the client's type exists and
// rclcpp::ok(). Sequence numbers start at 1 per client, like rmw.
#ifndef RCLCPP__CLIENT_HPP_
#define RCLCPP__CLIENT_HPP_

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <functional>
#include <future>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <tuple>
#include <type_traits>
#include <typeindex>
#include <unordered_map>
#include <utility>
#include <variant>
#include <vector>

#include "rclcpp/macros.hpp"
#include "rclcpp/qos.hpp"
#include "rclcpp/utilities.hpp"
#include "rclcpp/visibility_control.hpp"
#include "rmw/types.h"
#include "rosidl_runtime_cpp/traits.hpp"
#include "rhi_fake/detail/distro.hpp"
#include "rhi_fake/detail/function_traits.hpp"
#include "rhi_fake/detail/request_id.hpp"
#include "rhi_fake/detail/ros_core.hpp"

namespace rhi_fake {
namespace detail {

/// rclcpp::function_traits::same_arguments: the callable's parameter list is exactly that of F.
template<typename CallbackT, typename F, typename = void>
struct same_arguments : std::false_type {};

template<typename CallbackT, typename F>
struct same_arguments<CallbackT, F, std::void_t<typename ft::of<CallbackT>::arguments>>
  : std::is_same<typename ft::of<CallbackT>::arguments, typename ft::of<F>::arguments> {};

}  // namespace detail
}  // namespace rhi_fake

namespace rclcpp
{

namespace detail
{

/// A future and the sequence number of the request it waits for. Move-only (it owns the future).
template<typename FutureT>
struct FutureAndRequestId
{
  FutureT future;
  int64_t request_id;

  FutureAndRequestId(FutureT impl, int64_t req_id)
  : future(std::move(impl)), request_id(req_id) {}

  /// Implicit conversion to the future, by reference (every distro).
  operator FutureT &() {return this->future;}

#if RHI_FAKE_RCLCPP_MAJOR < 29
  /// By value: deprecated in Humble and Jazzy, removed from Kilted on.
  [[deprecated("FutureAndRequestId: use .future instead of an implicit conversion")]]
  operator FutureT() {return this->future;}
#endif

  auto get() {return this->future.get();}
  bool valid() const noexcept {return this->future.valid();}
  void wait() const {return this->future.wait();}

  template<class Rep, class Period>
  std::future_status wait_for(const std::chrono::duration<Rep, Period> & timeout_duration) const
  {
    return this->future.wait_for(timeout_duration);
  }

  template<class Clock, class Duration>
  std::future_status wait_until(const std::chrono::time_point<Clock, Duration> & timeout_time) const
  {
    return this->future.wait_until(timeout_time);
  }

  FutureAndRequestId(FutureAndRequestId && other) noexcept = default;
  FutureAndRequestId(const FutureAndRequestId & other) = delete;
  FutureAndRequestId & operator=(FutureAndRequestId && other) noexcept = default;
  FutureAndRequestId & operator=(const FutureAndRequestId & other) = delete;
  ~FutureAndRequestId() = default;
};

}  // namespace detail

class ClientBase : public ::rhi_fake::detail::ResponseSink
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS_NOT_COPYABLE(ClientBase)

  virtual ~ClientBase() = default;

  /// The expanded service name, e.g. "/aimdk_5Fmsgs/srv/MigrateSystemState".
  const char * get_service_name() const {return service_name_.c_str();}

  /// A live server of this client's service type exists (an in-process rclcpp::Service or the
  /// test's, rhi_fake/services.hpp). False once rclcpp is shut down (rclcpp's soft failure).
  bool service_is_ready() const
  {
    if (!rclcpp::ok()) {
      return false;
    }
    auto & reg = ::rhi_fake::detail::ros_registry();
    std::shared_ptr<void> keep;   // released outside the lock
    std::lock_guard<std::mutex> lock(reg.mutex);
    return ready_locked(reg, keep);
  }

  /// Waits until service_is_ready(); a negative timeout waits forever, zero checks once. False on
  /// timeout or when rclcpp is (or gets) shut down.
  template<typename RepT = int64_t, typename RatioT = std::milli>
  bool wait_for_service(
    std::chrono::duration<RepT, RatioT> timeout = std::chrono::duration<RepT, RatioT>(-1))
  {
    return wait_for_service_nanoseconds(
      std::chrono::duration_cast<std::chrono::nanoseconds>(timeout));
  }

  virtual std::shared_ptr<void> create_response() = 0;
  virtual std::shared_ptr<rmw_request_id_t> create_request_header() = 0;
  virtual void handle_response(
    std::shared_ptr<rmw_request_id_t> request_header, std::shared_ptr<void> response) = 0;

  rclcpp::QoS get_request_publisher_actual_qos() const {return qos_;}
  rclcpp::QoS get_response_subscription_actual_qos() const {return qos_;}

  /// Stand-in internals.
  std::uint64_t rhi_id() const {return id_;}
  std::shared_ptr<::rhi_fake::detail::NodeCore> rhi_sink_node() const override {return node_;}
  void rhi_take_response(std::int64_t sequence_number, std::shared_ptr<void> response) override
  {
    auto header = std::make_shared<rmw_request_id_t>();
    ::rhi_fake::detail::write_request_id(*header, id_, sequence_number);
    handle_response(std::move(header), std::move(response));
  }

protected:
  ClientBase(
    std::shared_ptr<::rhi_fake::detail::NodeCore> node, std::string service_name,
    const rclcpp::QoS & qos, std::type_index type)
  : node_(std::move(node)), service_name_(std::move(service_name)), qos_(qos), type_(type)
  {
    auto & reg = ::rhi_fake::detail::ros_registry();
    std::lock_guard<std::mutex> lock(reg.mutex);
    id_ = reg.next_client_id++;
  }

  ClientBase(const ClientBase &) = delete;
  ClientBase & operator=(const ClientBase &) = delete;

  bool wait_for_service_nanoseconds(std::chrono::nanoseconds timeout)
  {
    if (service_is_ready()) {
      return true;
    }
    if (timeout == std::chrono::nanoseconds(0)) {
      return false;
    }
    const auto start = std::chrono::steady_clock::now();
    auto & reg = ::rhi_fake::detail::ros_registry();
    std::shared_ptr<void> keep;   // declared before the lock: released after it
    std::unique_lock<std::mutex> lock(reg.mutex);
    while (true) {
      if (!rclcpp::ok()) {
        return false;
      }
      if (ready_locked(reg, keep)) {
        return true;
      }
      auto slice = std::chrono::nanoseconds(std::chrono::milliseconds(100));   // as rclcpp: re-check
      if (timeout > std::chrono::nanoseconds(0)) {
        const auto left = timeout - (std::chrono::steady_clock::now() - start);
        if (left <= std::chrono::nanoseconds(0)) {
          return false;
        }
        slice = std::min(slice, std::chrono::duration_cast<std::chrono::nanoseconds>(left));
      }
      reg.graph_cv.wait_for(lock, slice);
    }
  }

  /// Record the request under this name and hand it to the server (the test's, or the first live
  /// in-process one of this type); no server: the request is lost, as with rmw.
  void rhi_send(
    std::int64_t sequence_number, std::shared_ptr<const void> logged,
    std::shared_ptr<void> for_server)
  {
    auto & reg = ::rhi_fake::detail::ros_registry();
    std::shared_ptr<::rhi_fake::detail::FakeServer> fake;
    std::shared_ptr<::rhi_fake::detail::RequestSink> server;
    {
      std::lock_guard<std::mutex> lock(reg.mutex);
      auto & record = reg.services[service_name_];
      record.calls++;
      record.requests.emplace_back(type_, std::move(logged));
      if (record.fake && (record.fake->type == std::type_index(typeid(void)) || record.fake->type == type_)) {
        if (record.fake->mode == ::rhi_fake::detail::FakeServer::Mode::Hold) {
          record.held.push_back(::rhi_fake::detail::HeldRequest{id_, sequence_number, type_});
          return;
        }
        fake = record.fake;
      } else {
        for (auto & entry : record.servers) {
          if (entry.type != type_) {continue;}
          if (auto owner = entry.owner.lock()) {
            server = std::static_pointer_cast<::rhi_fake::detail::RequestSink>(owner);
            break;
          }
        }
      }
    }
    if (fake) {
      // The test's server answers on this thread; the response waits for the client's node.
      ::rhi_fake::detail::route_response(id_, sequence_number, fake->answer(for_server.get()));
    } else if (server) {
      ::rhi_fake::detail::post_request(server, id_, sequence_number, std::move(for_server));
    }
  }

  std::shared_ptr<::rhi_fake::detail::NodeCore> node_;
  std::string service_name_;
  rclcpp::QoS qos_;
  std::type_index type_;
  std::uint64_t id_ = 0;

private:
  // A live server of this type, or the test's (registry mutex held). `keep` takes the server so it
  // is released after the caller's lock.
  bool ready_locked(::rhi_fake::detail::RosRegistry & reg, std::shared_ptr<void> & keep) const
  {
    auto it = reg.services.find(service_name_);
    if (it == reg.services.end()) {
      return false;
    }
    const auto & fake = it->second.fake;
    if (fake && (fake->type == std::type_index(typeid(void)) || fake->type == type_)) {
      return true;
    }
    for (const auto & entry : it->second.servers) {
      if (entry.type == type_) {
        keep = entry.owner.lock();
        if (keep) {
          return true;
        }
      }
    }
    return false;
  }
};

template<typename ServiceT>
class Client : public ClientBase
{
  static_assert(
    rosidl_generator_traits::is_service<ServiceT>::value,
    "rclcpp::Client<ServiceT>: ServiceT must be a ROS service type (<pkg>/srv/<name>.hpp)");

public:
  using Request = typename ServiceT::Request;
  using Response = typename ServiceT::Response;

  using SharedRequest = typename ServiceT::Request::SharedPtr;
  using SharedResponse = typename ServiceT::Response::SharedPtr;

  using Promise = std::promise<SharedResponse>;
  using PromiseWithRequest = std::promise<std::pair<SharedRequest, SharedResponse>>;

  using SharedPromise = std::shared_ptr<Promise>;
  using SharedPromiseWithRequest = std::shared_ptr<PromiseWithRequest>;

  using Future = std::future<SharedResponse>;
  using SharedFuture = std::shared_future<SharedResponse>;
  using SharedFutureWithRequest = std::shared_future<std::pair<SharedRequest, SharedResponse>>;

  using CallbackType = std::function<void (SharedFuture)>;
  using CallbackWithRequestType = std::function<void (SharedFutureWithRequest)>;

  RCLCPP_SMART_PTR_DEFINITIONS(Client)

  /// What async_send_request(request) returns: `.future` is a std::future<SharedResponse>.
  struct FutureAndRequestId
    : detail::FutureAndRequestId<std::future<SharedResponse>>
  {
    using detail::FutureAndRequestId<std::future<SharedResponse>>::FutureAndRequestId;

#if RHI_FAKE_RCLCPP_MAJOR < 29
    /// Deprecated in Humble and Jazzy, removed from Kilted on.
    [[deprecated("FutureAndRequestId: use .future.share() instead of an implicit conversion")]]
    operator SharedFuture() {return this->future.share();}
#endif

    SharedFuture share() noexcept {return this->future.share();}
  };

  struct SharedFutureAndRequestId
    : detail::FutureAndRequestId<std::shared_future<SharedResponse>>
  {
    using detail::FutureAndRequestId<std::shared_future<SharedResponse>>::FutureAndRequestId;
  };

  struct SharedFutureWithRequestAndRequestId
    : detail::FutureAndRequestId<std::shared_future<std::pair<SharedRequest, SharedResponse>>>
  {
    using detail::FutureAndRequestId<
      std::shared_future<std::pair<SharedRequest, SharedResponse>>>::FutureAndRequestId;
  };

  /// Stand-in constructor (Node::create_client makes clients).
  Client(
    std::shared_ptr<::rhi_fake::detail::NodeCore> node, std::string service_name,
    const rclcpp::QoS & qos)
  : ClientBase(std::move(node), std::move(service_name), qos, std::type_index(typeid(ServiceT))) {}

  virtual ~Client() = default;

  std::shared_ptr<void> create_response() override {return std::make_shared<Response>();}

  std::shared_ptr<rmw_request_id_t> create_request_header() override
  {
    return std::make_shared<rmw_request_id_t>();
  }

  /// Completes the pending request `request_header->sequence_number` (unknown, removed or pruned
  /// ones are ignored, as in rclcpp). The fake calls it when the client's node is spun.
  void handle_response(
    std::shared_ptr<rmw_request_id_t> request_header, std::shared_ptr<void> response) override
  {
    std::optional<Pending> pending = take_pending(request_header->sequence_number);
    if (!pending) {
      return;
    }
    auto typed = std::static_pointer_cast<Response>(std::move(response));
    if (auto * promise = std::get_if<Promise>(&*pending)) {
      promise->set_value(std::move(typed));
    } else if (auto * with_cb = std::get_if<WithCallback>(&*pending)) {
      std::get<Promise>(*with_cb).set_value(std::move(typed));
      std::get<CallbackType>(*with_cb)(std::get<SharedFuture>(*with_cb));
    } else if (auto * with_req = std::get_if<WithRequestCallback>(&*pending)) {
      std::get<PromiseWithRequest>(*with_req).set_value(
        std::make_pair(std::get<SharedRequest>(*with_req), std::move(typed)));
      std::get<CallbackWithRequestType>(*with_req)(std::get<SharedFutureWithRequest>(*with_req));
    }
  }

  /// Send a request; the future completes when the client's node is spun after the server answered.
  FutureAndRequestId async_send_request(SharedRequest request)
  {
    Promise promise;
    auto future = promise.get_future();
    const auto id = send(request, Pending(std::move(promise)));
    return FutureAndRequestId(std::move(future), id);
  }

  /// Send a request; `cb(SharedFuture)` runs on the thread spinning the client's node.
  template<
    typename CallbackT,
    typename std::enable_if<
      ::rhi_fake::detail::same_arguments<CallbackT, CallbackType>::value>::type * = nullptr>
  SharedFutureAndRequestId async_send_request(SharedRequest request, CallbackT && cb)
  {
    Promise promise;
    auto shared_future = promise.get_future().share();
    const auto id = send(
      request,
      Pending(WithCallback(CallbackType{std::forward<CallbackT>(cb)}, shared_future, std::move(promise))));
    return SharedFutureAndRequestId(std::move(shared_future), id);
  }

  /// Send a request; `cb(SharedFutureWithRequest)` gets the (request, response) pair.
  template<
    typename CallbackT,
    typename std::enable_if<
      ::rhi_fake::detail::same_arguments<CallbackT, CallbackWithRequestType>::value>::type * = nullptr>
  SharedFutureWithRequestAndRequestId async_send_request(SharedRequest request, CallbackT && cb)
  {
    PromiseWithRequest promise;
    auto shared_future = promise.get_future().share();
    const auto id = send(
      request,
      Pending(
        WithRequestCallback(
          CallbackWithRequestType{std::forward<CallbackT>(cb)}, request, shared_future,
          std::move(promise))));
    return SharedFutureWithRequestAndRequestId(std::move(shared_future), id);
  }

  /// Forget a pending request (its response, if it comes, is ignored); false if unknown.
  bool remove_pending_request(int64_t request_id)
  {
    std::lock_guard<std::mutex> guard(pending_requests_mutex_);
    return pending_requests_.erase(request_id) != 0u;
  }

  bool remove_pending_request(const FutureAndRequestId & future)
  {
    return this->remove_pending_request(future.request_id);
  }

  bool remove_pending_request(const SharedFutureAndRequestId & future)
  {
    return this->remove_pending_request(future.request_id);
  }

  bool remove_pending_request(const SharedFutureWithRequestAndRequestId & future)
  {
    return this->remove_pending_request(future.request_id);
  }

  /// Forget every pending request; returns how many.
  size_t prune_pending_requests()
  {
    std::lock_guard<std::mutex> guard(pending_requests_mutex_);
    const auto n = pending_requests_.size();
    pending_requests_.clear();
    return n;
  }

  /// Forget the pending requests sent before `time_point` (their ids go to `pruned_requests`).
  template<typename AllocatorT = std::allocator<int64_t>>
  size_t prune_requests_older_than(
    std::chrono::time_point<std::chrono::system_clock> time_point,
    std::vector<int64_t, AllocatorT> * pruned_requests = nullptr)
  {
    std::lock_guard<std::mutex> guard(pending_requests_mutex_);
    size_t n = 0;
    for (auto it = pending_requests_.begin(); it != pending_requests_.end(); ) {
      if (it->second.first < time_point) {
        if (pruned_requests) {
          pruned_requests->push_back(it->first);
        }
        it = pending_requests_.erase(it);
        ++n;
      } else {
        ++it;
      }
    }
    return n;
  }

protected:
  using WithCallback = std::tuple<CallbackType, SharedFuture, Promise>;
  using WithRequestCallback =
    std::tuple<CallbackWithRequestType, SharedRequest, SharedFutureWithRequest, PromiseWithRequest>;
  using Pending = std::variant<Promise, WithCallback, WithRequestCallback>;

  int64_t send(const SharedRequest & request, Pending value)
  {
    if (!request) {
      // rclcpp dereferences it (a crash); the stand-in says so instead
      throw std::invalid_argument("rclcpp::Client::async_send_request: null request");
    }
    int64_t sequence_number = 0;
    {
      std::lock_guard<std::mutex> guard(pending_requests_mutex_);
      sequence_number = next_sequence_number_++;
      pending_requests_.emplace(
        sequence_number, std::make_pair(std::chrono::system_clock::now(), std::move(value)));
    }
    // What rmw would serialize: the server and the test's log each get their own copy.
    rhi_send(
      sequence_number, std::make_shared<const Request>(*request), std::make_shared<Request>(*request));
    return sequence_number;
  }

  std::optional<Pending> take_pending(int64_t request_number)
  {
    std::lock_guard<std::mutex> guard(pending_requests_mutex_);
    auto it = pending_requests_.find(request_number);
    if (it == pending_requests_.end()) {
      return std::nullopt;
    }
    std::optional<Pending> value(std::move(it->second.second));
    pending_requests_.erase(it);
    return value;
  }

  std::unordered_map<
    int64_t, std::pair<std::chrono::time_point<std::chrono::system_clock>, Pending>> pending_requests_;
  std::mutex pending_requests_mutex_;
  int64_t next_sequence_number_ = 1;   // under pending_requests_mutex_
};

}  // namespace rclcpp

#endif  // RCLCPP__CLIENT_HPP_
