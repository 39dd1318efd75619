// rhi-gen test stand-in (not the real ROS 2 code): rclcpp::ServiceBase / rclcpp::Service<ServiceT>
// (the same API on rclcpp 16, 28 and 29+, but Jazzy's configure_introspection, not modelled).
// Node::create_service<ServiceT>(name, callback, qos, group) makes them; the callback forms are those
// of rclcpp/any_service_callback.hpp.
//
// Fake transport: a client's request is queued on the service's node and the callback runs when an
// executor spins that node (under the node's callback mutex, like rclcpp's default mutually exclusive
// group); its response is queued on the client's node. A deferred-response callback answers later
// with send_response(header, response) (from any thread). rhi_fake::services::call() runs the
// callback now on the test's thread instead.
#ifndef RCLCPP__SERVICE_HPP_
#define RCLCPP__SERVICE_HPP_

#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <typeindex>
#include <utility>

#include "rclcpp/any_service_callback.hpp"
#include "rclcpp/macros.hpp"
#include "rclcpp/qos.hpp"
#include "rclcpp/visibility_control.hpp"
#include "rmw/types.h"
#include "rosidl_runtime_cpp/traits.hpp"
#include "rhi_fake/detail/request_id.hpp"
#include "rhi_fake/detail/ros_core.hpp"

namespace rclcpp
{

class ServiceBase : public ::rhi_fake::detail::RequestSink
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS_NOT_COPYABLE(ServiceBase)

  virtual ~ServiceBase() = default;

  /// The expanded service name.
  const char * get_service_name() {return service_name_.c_str();}

  virtual std::shared_ptr<void> create_request() = 0;
  virtual std::shared_ptr<rmw_request_id_t> create_request_header() = 0;
  virtual void handle_request(
    std::shared_ptr<rmw_request_id_t> request_header, std::shared_ptr<void> request) = 0;

  rclcpp::QoS get_response_publisher_actual_qos() const {return qos_;}
  rclcpp::QoS get_request_subscription_actual_qos() const {return qos_;}

  /// Stand-in internals.
  std::shared_ptr<::rhi_fake::detail::NodeCore> rhi_sink_node() const override {return node_;}
  std::type_index rhi_type() const {return type_;}
  void rhi_take_request(
    std::uint64_t client_id, std::int64_t sequence_number, std::shared_ptr<void> request) override
  {
    auto header = std::make_shared<rmw_request_id_t>();
    ::rhi_fake::detail::write_request_id(*header, client_id, sequence_number);
    handle_request(std::move(header), std::move(request));
  }

protected:
  ServiceBase(
    std::shared_ptr<::rhi_fake::detail::NodeCore> node, std::string service_name,
    const rclcpp::QoS & qos, std::type_index type)
  : node_(std::move(node)), service_name_(std::move(service_name)), qos_(qos), type_(type) {}

  ServiceBase(const ServiceBase &) = delete;
  ServiceBase & operator=(const ServiceBase &) = delete;

  std::shared_ptr<::rhi_fake::detail::NodeCore> node_;
  std::string service_name_;
  rclcpp::QoS qos_;
  std::type_index type_;
};

template<typename ServiceT>
class Service
  : public ServiceBase,
  public std::enable_shared_from_this<Service<ServiceT>>
{
  static_assert(
    rosidl_generator_traits::is_service<ServiceT>::value,
    "rclcpp::Service<ServiceT>: ServiceT must be a ROS service type (<pkg>/srv/<name>.hpp)");

public:
  using CallbackType = std::function<
    void (
      const std::shared_ptr<typename ServiceT::Request>,
      std::shared_ptr<typename ServiceT::Response>)>;
  using CallbackWithHeaderType = std::function<
    void (
      const std::shared_ptr<rmw_request_id_t>,
      const std::shared_ptr<typename ServiceT::Request>,
      std::shared_ptr<typename ServiceT::Response>)>;

  RCLCPP_SMART_PTR_DEFINITIONS(Service)

  /// Stand-in constructor (Node::create_service makes services).
  Service(
    std::shared_ptr<::rhi_fake::detail::NodeCore> node, std::string service_name,
    AnyServiceCallback<ServiceT> any_callback, const rclcpp::QoS & qos)
  : ServiceBase(std::move(node), std::move(service_name), qos, std::type_index(typeid(ServiceT))),
    any_callback_(std::move(any_callback)) {}

  Service() = delete;
  virtual ~Service() = default;

  std::shared_ptr<void> create_request() override
  {
    return std::make_shared<typename ServiceT::Request>();
  }

  std::shared_ptr<rmw_request_id_t> create_request_header() override
  {
    return std::make_shared<rmw_request_id_t>();
  }

  void handle_request(
    std::shared_ptr<rmw_request_id_t> request_header, std::shared_ptr<void> request) override
  {
    auto typed_request = std::static_pointer_cast<typename ServiceT::Request>(std::move(request));
    auto response = any_callback_.dispatch(this->shared_from_this(), request_header, typed_request);
    if (response) {
      send_response(*request_header, *response);
    }
  }

  /// Answer request `req_id` (a copy of `response` goes to the client, which gets it when its node
  /// is spun). A client that no longer exists is ignored, as rmw does.
  void send_response(rmw_request_id_t & req_id, typename ServiceT::Response & response)
  {
    ::rhi_fake::detail::route_response(
      ::rhi_fake::detail::client_id_of(req_id), req_id.sequence_number,
      std::make_shared<typename ServiceT::Response>(response));
  }

  /// Stand-in internal (rhi_fake::services::call): run the callback, return its response unsent.
  std::optional<typename ServiceT::Response> rhi_call_now(
    const std::shared_ptr<rmw_request_id_t> & request_header,
    std::shared_ptr<typename ServiceT::Request> request)
  {
    auto response = any_callback_.dispatch(this->shared_from_this(), request_header, std::move(request));
    if (!response) {
      return std::nullopt;
    }
    return *response;
  }

private:
  Service(const Service &) = delete;
  Service & operator=(const Service &) = delete;

  AnyServiceCallback<ServiceT> any_callback_;
};

}  // namespace rclcpp

#endif  // RCLCPP__SERVICE_HPP_
