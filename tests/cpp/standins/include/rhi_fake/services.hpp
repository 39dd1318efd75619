// rhi-gen test hooks for the fake rclcpp services (test code only; generated drivers never include
// this). Namespace rhi_fake::services. All functions are thread-safe. Service arguments: absolute
// ("/aimdk_5Fmsgs/srv/MigrateSystemState") or relative (same with a leading '/'); drivers' names
// are expanded by the Node. See tests/cpp/standins/README.md (§2b) for the contract.
//
// The test can play the server of a service name (the real one runs in another process, e.g. the
// AimDK system-state manager):
//   serve<S>(name, handler)      answer every request with handler(request, response); it runs on
//                                the thread that sends the request, inside async_send_request()
//   serve<S>(name, response)     answer every request with a copy of `response`
//   hold(name)                   accept requests (service_is_ready() is true) but answer none until
//                                answer_held<S>(name, response): what a timeout test needs
//   unserve(name)                the test's server is gone (service_is_ready() false unless an
//                                in-process rclcpp::Service of that name exists)
// Either way the response reaches the client when the *client's* node is spun (its executor's
// spin(), spin_some() or spin_until_future_complete()), as with rclcpp. ROS 2 services cannot
// refuse a request at the transport level: "refusing" is a response saying so (e.g. a failure code)
// or no answer at all (hold).
#pragma once

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
#include "rhi_fake/detail/request_id.hpp"
#include "rhi_fake/detail/ros_core.hpp"

namespace rhi_fake {
namespace services {

namespace detail_ {

inline std::string key_of(std::string_view service)
{
  char buffer[512];
  return std::string(::rhi_fake::detail::hook_topic_key(service, buffer));
}

template<typename ServiceT>
void set_answer(
  std::string_view service,
  std::function<void(const typename ServiceT::Request &, typename ServiceT::Response &)> handler)
{
  if (!handler) {
    throw std::invalid_argument("rhi_fake::services::serve: empty handler");
  }
  auto fake = std::make_shared<::rhi_fake::detail::FakeServer>();
  fake->mode = ::rhi_fake::detail::FakeServer::Mode::Answer;
  fake->type = std::type_index(typeid(ServiceT));
  fake->type_name = rosidl_generator_traits::name<ServiceT>();
  fake->answer = [handler = std::move(handler)](const void * request) -> std::shared_ptr<void> {
      auto response = std::make_shared<typename ServiceT::Response>();
      handler(*static_cast<const typename ServiceT::Request *>(request), *response);
      return response;
    };
  auto & reg = ::rhi_fake::detail::ros_registry();
  {
    std::lock_guard<std::mutex> lock(reg.mutex);
    auto & record = reg.services[key_of(service)];
    record.fake = std::move(fake);
  }
  reg.graph_cv.notify_all();
}

}  // namespace detail_

/// Play the server of `service` (type ServiceT): every request gets handler(request, response).
template<typename ServiceT>
void serve(
  std::string_view service,
  std::function<void(const typename ServiceT::Request &, typename ServiceT::Response &)> handler)
{
  detail_::set_answer<ServiceT>(service, std::move(handler));
}

/// Play the server of `service`: every request gets a copy of `response`.
template<typename ServiceT>
void serve(std::string_view service, const typename ServiceT::Response & response)
{
  detail_::set_answer<ServiceT>(
    service,
    [response](const typename ServiceT::Request &, typename ServiceT::Response & out) {out = response;});
}

/// Play a server of `service` (any type) that answers nothing until answer_held().
inline void hold(std::string_view service)
{
  auto fake = std::make_shared<::rhi_fake::detail::FakeServer>();
  fake->mode = ::rhi_fake::detail::FakeServer::Mode::Hold;
  auto & reg = ::rhi_fake::detail::ros_registry();
  {
    std::lock_guard<std::mutex> lock(reg.mutex);
    reg.services[detail_::key_of(service)].fake = std::move(fake);
  }
  reg.graph_cv.notify_all();
}

/// Stop playing the server of `service` (held requests stay unanswered).
inline void unserve(std::string_view service)
{
  auto & reg = ::rhi_fake::detail::ros_registry();
  std::shared_ptr<::rhi_fake::detail::FakeServer> gone;   // destroyed outside the lock
  std::lock_guard<std::mutex> lock(reg.mutex);
  auto it = reg.services.find(detail_::key_of(service));
  if (it != reg.services.end()) {
    gone = std::move(it->second.fake);
    it->second.held.clear();
  }
}

/// Requests held by hold(service) and not answered yet.
inline std::size_t held_count(std::string_view service)
{
  auto & reg = ::rhi_fake::detail::ros_registry();
  std::lock_guard<std::mutex> lock(reg.mutex);
  auto it = reg.services.find(detail_::key_of(service));
  return it == reg.services.end() ? 0 : it->second.held.size();
}

/// Answer every held request of `service` with a copy of `response` (each reaches its client when
/// the client's node is spun). Returns how many were answered; throws std::logic_error if a held
/// request is of another service type (nothing is answered then).
template<typename ServiceT>
std::size_t answer_held(std::string_view service, const typename ServiceT::Response & response)
{
  std::vector<::rhi_fake::detail::HeldRequest> held;
  {
    auto & reg = ::rhi_fake::detail::ros_registry();
    std::lock_guard<std::mutex> lock(reg.mutex);
    auto it = reg.services.find(detail_::key_of(service));
    if (it == reg.services.end()) {
      return 0;
    }
    for (const auto & h : it->second.held) {
      if (h.type != std::type_index(typeid(ServiceT))) {
        throw std::logic_error(
                "rhi_fake::services::answer_held: a request held on '" + it->first +
                "' is of another service type");
      }
    }
    held.swap(it->second.held);
  }
  std::size_t answered = 0;
  for (const auto & h : held) {
    if (::rhi_fake::detail::route_response(
        h.client_id, h.sequence_number, std::make_shared<typename ServiceT::Response>(response)))
    {
      ++answered;
    }
  }
  return answered;
}

/// Copies of every request sent to `service` (by any client, answered or not), oldest first.
/// Throws std::logic_error if one of them is of another service type.
template<typename ServiceT>
std::vector<typename ServiceT::Request> requests(std::string_view service)
{
  std::vector<std::shared_ptr<const void>> found;
  {
    auto & reg = ::rhi_fake::detail::ros_registry();
    std::lock_guard<std::mutex> lock(reg.mutex);
    auto it = reg.services.find(detail_::key_of(service));
    if (it == reg.services.end()) {
      return {};
    }
    for (const auto & [type, request] : it->second.requests) {
      if (type != std::type_index(typeid(ServiceT))) {
        throw std::logic_error(
                "rhi_fake::services::requests: '" + it->first + "' got requests of another type");
      }
      found.push_back(request);
    }
  }
  std::vector<typename ServiceT::Request> out;
  out.reserve(found.size());
  for (const auto & request : found) {
    out.push_back(*static_cast<const typename ServiceT::Request *>(request.get()));
  }
  return out;
}

/// Number of requests sent to `service` (async_send_request calls, answered or not).
inline std::uint64_t call_count(std::string_view service)
{
  auto & reg = ::rhi_fake::detail::ros_registry();
  std::lock_guard<std::mutex> lock(reg.mutex);
  auto it = reg.services.find(detail_::key_of(service));
  return it == reg.services.end() ? 0 : it->second.calls;
}

/// Call the in-process server of `service` (e.g. one a driver offers) now, on this thread, under
/// its node's callback mutex, as a client would: the request is recorded like a client's. Returns
/// the response; nullopt when there is no live server of that type or its callback defers the
/// response (a later send_response() to this call is dropped).
template<typename ServiceT>
std::optional<typename ServiceT::Response> call(
  std::string_view service, const typename ServiceT::Request & request)
{
  std::shared_ptr<rclcpp::Service<ServiceT>> server;
  {
    auto & reg = ::rhi_fake::detail::ros_registry();
    std::lock_guard<std::mutex> lock(reg.mutex);
    auto & record = reg.services[detail_::key_of(service)];
    record.calls++;
    record.requests.emplace_back(
      std::type_index(typeid(ServiceT)), std::make_shared<const typename ServiceT::Request>(request));
    for (auto & entry : record.servers) {
      if (entry.type != std::type_index(typeid(ServiceT))) {continue;}
      if (auto owner = entry.owner.lock()) {
        auto sink = std::static_pointer_cast<::rhi_fake::detail::RequestSink>(owner);
        server = std::static_pointer_cast<rclcpp::Service<ServiceT>>(
          std::static_pointer_cast<rclcpp::ServiceBase>(sink));
        break;
      }
    }
  }
  if (!server) {
    return std::nullopt;
  }
  // Run the callback as the executor would, keeping its response. The request id names client 0,
  // which never exists: a deferred send_response() for it goes nowhere.
  auto header = std::make_shared<rmw_request_id_t>();
  ::rhi_fake::detail::write_request_id(*header, 0, 0);
  auto node = server->rhi_sink_node();
  std::lock_guard<std::recursive_mutex> lock(node->callback_mutex);
  return server->rhi_call_now(header, std::make_shared<typename ServiceT::Request>(request));
}

// ------------------------------------------------------------------ graph

struct EndpointInfo
{
  std::string node;        // fully qualified node name
  std::string type_name;   // e.g. "aimdk_msgs/srv/MigrateSystemState"
};

struct ServiceInfo
{
  std::string name;                       // e.g. "/aimdk_5Fmsgs/srv/MigrateSystemState"
  std::vector<EndpointInfo> servers;      // live in-process rclcpp::Service objects
  std::vector<EndpointInfo> clients;      // live rclcpp::Client objects
  std::string fake;                       // the test's server: "", "answer" or "hold"
  std::string fake_type_name;             // its service type ("" for hold: any)
  std::uint64_t calls;                    // call_count()
  std::size_t held;                       // held_count()
};

/// Every service name that has (or had) a server, client or test server, sorted by name.
inline std::vector<ServiceInfo> list()
{
  std::vector<ServiceInfo> out;
  auto & reg = ::rhi_fake::detail::ros_registry();
  std::lock_guard<std::mutex> lock(reg.mutex);
  for (const auto & [name, record] : reg.services) {
    ServiceInfo info{name, {}, {}, "", "", record.calls, record.held.size()};
    for (const auto & e : record.servers) {
      if (!e.owner.expired()) {info.servers.push_back(EndpointInfo{e.node, e.type_name});}
    }
    for (const auto & e : record.clients) {
      if (!e.owner.expired()) {info.clients.push_back(EndpointInfo{e.node, e.type_name});}
    }
    if (record.fake) {
      const bool answer = record.fake->mode == ::rhi_fake::detail::FakeServer::Mode::Answer;
      info.fake = answer ? "answer" : "hold";
      info.fake_type_name = record.fake->type_name;
    }
    out.push_back(std::move(info));
  }
  return out;
}

/// One service, if known.
inline std::optional<ServiceInfo> info(std::string_view service)
{
  const std::string key = detail_::key_of(service);
  for (auto & s : list()) {
    if (s.name == key) {return s;}
  }
  return std::nullopt;
}

/// Forget every service record, test server and held request (ros::reset() does it too).
inline void reset()
{
  auto & reg = ::rhi_fake::detail::ros_registry();
  std::map<std::string, ::rhi_fake::detail::ServiceRecord, std::less<>> gone;   // freed unlocked
  std::lock_guard<std::mutex> lock(reg.mutex);
  gone.swap(reg.services);
  reg.clients_by_id.clear();
}

}  // namespace services
}  // namespace rhi_fake
