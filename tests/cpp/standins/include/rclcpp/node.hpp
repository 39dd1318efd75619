// rhi-gen test stand-in (not the real ROS 2 code): rclcpp::Node (ROS 2 Humble API subset):
// names, logger, clock, now(), create_publisher, create_subscription, create_wall_timer,
// create_client / create_service (per distro: Humble takes an rmw_qos_profile_t; Jazzy adds the
// rclcpp::QoS overloads and deprecates the rmw_qos_profile_t ones; Kilted and later only take QoS),
// get_node_base_interface / get_node_clock_interface / get_node_logging_interface, and statically
// typed scalar parameters: declare_parameter, get_parameter, set_parameter, add_on_set_parameters_callback
// (callbacks run newest first, a failed one rejects the set; a value of another type is rejected with
// rclcpp's reason; parameter overrides from NodeOptions / --ros-args are not modelled). Like rclcpp:
//  * constructing a Node before rclcpp::init() (or after shutdown) throws rclcpp::exceptions::RCLError;
//  * invalid node names / namespaces / topic names throw the rclcpp::exceptions::Invalid*Error types;
//  * topic names are expanded: "x" -> "<ns>/x", "~/x" -> "<node fqn>/x".
// This header does NOT include rclcpp/logging.hpp (neither does the real one directly): include it
// (or rclcpp/rclcpp.hpp) for the RCLCPP_* macros.
#ifndef RCLCPP__NODE_HPP_
#define RCLCPP__NODE_HPP_

#include <cctype>
#include <chrono>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <typeindex>
#include <utility>
#include <vector>

#include "rcl/time.h"
#include "rhi_fake/detail/distro.hpp"
#include "rmw/qos_profiles.h"
#include "rcl_interfaces/msg/parameter_descriptor.hpp"
#include "rcl_interfaces/msg/set_parameters_result.hpp"
#include "rclcpp/callback_group.hpp"
#include "rclcpp/client.hpp"
#include "rclcpp/clock.hpp"
#include "rclcpp/context.hpp"
#include "rclcpp/duration.hpp"
#include "rclcpp/exceptions.hpp"
#include "rclcpp/logger.hpp"
#include "rclcpp/macros.hpp"
#include "rclcpp/node_interfaces/node_parameters_interface.hpp"
#include "rclcpp/parameter.hpp"
#include "rclcpp/parameter_value.hpp"
#include "rclcpp/node_interfaces/node_base_interface.hpp"
#include "rclcpp/node_interfaces/node_clock_interface.hpp"
#include "rclcpp/node_interfaces/node_logging_interface.hpp"
#include "rclcpp/node_options.hpp"
#include "rclcpp/publisher.hpp"
#include "rclcpp/publisher_options.hpp"
#include "rclcpp/qos.hpp"
#include "rclcpp/service.hpp"
#include "rclcpp/subscription.hpp"
#include "rclcpp/subscription_options.hpp"
#include "rclcpp/time.hpp"
#include "rclcpp/timer.hpp"
#include "rclcpp/utilities.hpp"
#include "rclcpp/visibility_control.hpp"
#include "rosidl_runtime_cpp/traits.hpp"
#include "rhi_fake/detail/ros_core.hpp"

namespace rhi_fake {
namespace detail {

inline void validate_node_name(const std::string & name)
{
  if (name.empty()) {
    throw rclcpp::exceptions::InvalidNodeNameError(name.c_str(), "node name must not be empty", 0);
  }
  if (name.size() > 255) {
    throw rclcpp::exceptions::InvalidNodeNameError(name.c_str(), "node name is too long", 255);
  }
  for (size_t i = 0; i < name.size(); ++i) {
    unsigned char c = static_cast<unsigned char>(name[i]);
    if (!(std::isalnum(c) || c == '_')) {
      throw rclcpp::exceptions::InvalidNodeNameError(
              name.c_str(), "node name must not contain characters other than alphanumerics or '_'", i);
    }
  }
  if (std::isdigit(static_cast<unsigned char>(name[0]))) {
    throw rclcpp::exceptions::InvalidNodeNameError(
            name.c_str(), "node name must not start with a number", 0);
  }
}

inline std::string normalize_namespace(const std::string & ns)
{
  if (ns.empty() || ns == "/") {
    return "/";
  }
  std::string out = ns.front() == '/' ? ns : "/" + ns;
  if (out.size() > 1 && out.back() == '/') {
    throw rclcpp::exceptions::InvalidNamespaceError(
            ns.c_str(), "namespace must not end with a forward slash", ns.size() - 1);
  }
  for (size_t i = 0; i < out.size(); ++i) {
    unsigned char c = static_cast<unsigned char>(out[i]);
    bool ok = std::isalnum(c) || c == '_' || c == '/';
    bool double_slash = c == '/' && i + 1 < out.size() && out[i + 1] == '/';
    bool digit_token = std::isdigit(c) && i > 0 && out[i - 1] == '/';
    if (!ok || double_slash || digit_token) {
      throw rclcpp::exceptions::InvalidNamespaceError(ns.c_str(), "invalid namespace", i);
    }
  }
  return out;
}

/// rcl's logger name of a node: "<ns without leading '/', '/' -> '.'>.<name>", or "<name>".
inline std::string node_logger_name(const std::string & name, const std::string & ns)
{
  std::string prefix;
  for (char c : ns) {
    if (c == '/') {
      if (!prefix.empty() && prefix.back() != '.') {prefix += '.';}
    } else {
      prefix += c;
    }
  }
  if (!prefix.empty() && prefix.back() == '.') {prefix.pop_back();}
  return prefix.empty() ? name : prefix + "." + name;
}

/// Expand and validate a topic (or service) name the way rcl does for the default (no remapping)
/// case; an invalid service name throws InvalidServiceNameError (the messages say "topic name", as
/// rcl's validation does for both).
inline std::string expand_topic_name(
  const std::string & name, const NodeCore & node, bool is_service = false)
{
  auto fail = [&](const char * why, size_t at) {
      if (is_service) {
        throw rclcpp::exceptions::InvalidServiceNameError(name.c_str(), why, at);
      }
      throw rclcpp::exceptions::InvalidTopicNameError(name.c_str(), why, at);
    };
  if (name.empty()) {fail("topic name must not be empty", 0);}
  if (name.back() == '/') {fail("topic name must not end with a forward slash", name.size() - 1);}
  for (size_t i = 0; i < name.size(); ++i) {
    unsigned char c = static_cast<unsigned char>(name[i]);
    if (c == '~') {
      if (i != 0 || (name.size() > 1 && name[1] != '/')) {
        fail("'~' must be followed by a '/' and only be the first character", i);
      }
      continue;
    }
    if (!(std::isalnum(c) || c == '_' || c == '/')) {
      fail("topic name must not contain characters other than alphanumerics, '_', '~' or '/'", i);
    }
    if (c == '/' && i + 1 < name.size() && name[i + 1] == '/') {
      fail("topic name must not contain repeated forward slashes", i);
    }
    if (std::isdigit(c) && (i == 0 || name[i - 1] == '/')) {
      fail("topic name tokens must not start with a number", i);
    }
  }
  std::string out;
  if (name[0] == '/') {
    out = name;
  } else if (name[0] == '~') {
    out = node.fqn + name.substr(1);
  } else {
    out = (node.ns == "/" ? std::string("/") : node.ns + "/") + name;
  }
  return out;
}

template<typename EntityT>
inline EndpointEntry make_endpoint(
  const std::shared_ptr<EntityT> & owner, const rclcpp::QoS & qos, const NodeCore & node,
  std::type_index type, const char * type_name)
{
  const auto & p = qos.get_rmw_qos_profile();
  QosSnapshot snap;
  snap.history = static_cast<int>(p.history);
  snap.depth = p.depth;
  snap.reliability = static_cast<int>(p.reliability);
  snap.durability = static_cast<int>(p.durability);
  return EndpointEntry{std::weak_ptr<void>(owner), snap, node.fqn, type, type_name};
}

}  // namespace detail
}  // namespace rhi_fake

namespace rhi_fake {
namespace detail {
// The node's clock and logger behind the abstract rclcpp node interfaces.
class NodeClock final : public rclcpp::node_interfaces::NodeClockInterface
{
public:
  explicit NodeClock(rclcpp::Clock::SharedPtr clock)
  : clock_(std::move(clock)) {}
  rclcpp::Clock::SharedPtr get_clock() override {return clock_;}
  rclcpp::Clock::ConstSharedPtr get_clock() const override {return clock_;}

private:
  rclcpp::Clock::SharedPtr clock_;
};

class NodeLogging final : public rclcpp::node_interfaces::NodeLoggingInterface
{
public:
  explicit NodeLogging(rclcpp::Logger logger)
  : logger_(std::move(logger)) {}
  rclcpp::Logger get_logger() const override {return logger_;}
  const char * get_logger_name() const override {return logger_.get_name();}

private:
  rclcpp::Logger logger_;
};
}  // namespace detail
}  // namespace rhi_fake

namespace rclcpp
{

class Node : public std::enable_shared_from_this<Node>
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(Node)

  explicit Node(const std::string & node_name, const NodeOptions & options = NodeOptions())
  : Node(node_name, "", options) {}

  explicit Node(
    const std::string & node_name, const std::string & namespace_,
    const NodeOptions & options = NodeOptions())
  : options_(options),
    logger_(rclcpp::get_logger(::rhi_fake::detail::node_logger_name(node_name, namespace_))),
    clock_(std::make_shared<rclcpp::Clock>(RCL_ROS_TIME))
  {
    if (!rclcpp::ok()) {
      throw rclcpp::exceptions::RCLError(
              "failed to initialize rcl node: the given context is not valid (call rclcpp::init() "
              "first), at ./src/rcl/node.c");
    }
    ::rhi_fake::detail::validate_node_name(node_name);
    core_ = std::make_shared<::rhi_fake::detail::NodeCore>();
    core_->name = node_name;
    core_->ns = ::rhi_fake::detail::normalize_namespace(namespace_);
    core_->fqn = (core_->ns == "/" ? std::string("/") : core_->ns + "/") + node_name;
    base_ = std::make_shared<node_interfaces::NodeBaseInterface>(core_);
    clock_if_ = std::make_shared<::rhi_fake::detail::NodeClock>(clock_);
    logging_if_ = std::make_shared<::rhi_fake::detail::NodeLogging>(logger_);
  }

  virtual ~Node() = default;

  const char * get_name() const {return core_->name.c_str();}
  const char * get_namespace() const {return core_->ns.c_str();}
  const char * get_fully_qualified_name() const {return core_->fqn.c_str();}

  rclcpp::Logger get_logger() const {return logger_;}

  rclcpp::Clock::SharedPtr get_clock() {return clock_;}
  rclcpp::Clock::ConstSharedPtr get_clock() const {return clock_;}

  /// Current time of the node clock (RCL_ROS_TIME; system time unless a fake time is set).
  Time now() const {return clock_->now();}

  const NodeOptions & get_node_options() const {return options_;}

  node_interfaces::NodeBaseInterface::SharedPtr get_node_base_interface() {return base_;}

  node_interfaces::NodeClockInterface::SharedPtr get_node_clock_interface() {return clock_if_;}

  node_interfaces::NodeLoggingInterface::SharedPtr get_node_logging_interface() {return logging_if_;}

  template<
    typename MessageT,
    typename AllocatorT = std::allocator<void>,
    typename PublisherT = rclcpp::Publisher<MessageT, AllocatorT>>
  std::shared_ptr<PublisherT>
  create_publisher(
    const std::string & topic_name,
    const rclcpp::QoS & qos,
    const PublisherOptionsWithAllocator<AllocatorT> & options =
    PublisherOptionsWithAllocator<AllocatorT>())
  {
    (void)options;
    static_assert(
      rosidl_generator_traits::is_message<MessageT>::value,
      "create_publisher<MessageT>: MessageT must be a ROS message type");
    std::string topic = ::rhi_fake::detail::expand_topic_name(topic_name, *core_);
    const std::type_index type(typeid(MessageT));
    const char * type_name = rosidl_generator_traits::name<MessageT>();
    auto & reg = ::rhi_fake::detail::ros_registry();
    std::lock_guard<std::mutex> lock(reg.mutex);
    auto & record = reg.topics[topic];
    if (!record.slot) {
      record.slot = std::make_shared<::rhi_fake::detail::TopicSlot<MessageT>>(type, type_name);
    } else if (record.slot->type != type) {
      throw std::logic_error(
              "rhi_fake: topic '" + topic + "' already has a publisher of type " +
              record.slot->type_name + "; the fake keeps one message type per published topic");
    }
    auto slot = std::static_pointer_cast<::rhi_fake::detail::TopicSlot<MessageT>>(record.slot);
    auto pub = std::make_shared<PublisherT>(core_, topic, qos, slot);
    ::rhi_fake::detail::prune_dead(record.publishers);
    record.publishers.push_back(
      ::rhi_fake::detail::make_endpoint(
        std::shared_ptr<rclcpp::PublisherBase>(pub), qos, *core_, type, type_name));
    return pub;
  }

  template<
    typename MessageT,
    typename CallbackT,
    typename AllocatorT = std::allocator<void>,
    typename SubscriptionT = rclcpp::Subscription<MessageT, AllocatorT>>
  std::shared_ptr<SubscriptionT>
  create_subscription(
    const std::string & topic_name,
    const rclcpp::QoS & qos,
    CallbackT && callback,
    const SubscriptionOptionsWithAllocator<AllocatorT> & options =
    SubscriptionOptionsWithAllocator<AllocatorT>())
  {
    (void)options;
    static_assert(
      rosidl_generator_traits::is_message<MessageT>::value,
      "create_subscription<MessageT>: MessageT must be a ROS message type");
    using DecayedT = std::decay_t<CallbackT>;
    using cb_traits = ::rhi_fake::detail::subscription_callback_traits<MessageT, DecayedT>;
    constexpr auto kind = cb_traits::kind;
    if constexpr (kind == ::rhi_fake::detail::CallbackKind::SharedPtr) {
      ::rhi_fake::detail::shared_ptr_callback_is_deprecated<MessageT>();
    }
    using ImplT = ::rhi_fake::detail::SubscriptionImpl<MessageT, AllocatorT, DecayedT, kind>;
    std::string topic = ::rhi_fake::detail::expand_topic_name(topic_name, *core_);
    auto impl = std::make_shared<ImplT>(core_, topic, qos, DecayedT(std::forward<CallbackT>(callback)));
    std::shared_ptr<SubscriptionT> sub = impl;
    const std::type_index type(typeid(MessageT));
    auto & reg = ::rhi_fake::detail::ros_registry();
    std::lock_guard<std::mutex> lock(reg.mutex);
    auto & record = reg.topics[topic];
    ::rhi_fake::detail::prune_dead(record.subscriptions);
    record.subscriptions.push_back(
      ::rhi_fake::detail::make_endpoint(
        std::shared_ptr<rclcpp::SubscriptionBase>(sub), qos, *core_, type,
        rosidl_generator_traits::name<MessageT>()));
    return sub;
  }

  template<typename DurationRepT = int64_t, typename DurationT = std::milli, typename CallbackT>
  typename rclcpp::WallTimer<CallbackT>::SharedPtr
  create_wall_timer(
    std::chrono::duration<DurationRepT, DurationT> period,
    CallbackT callback,
    rclcpp::CallbackGroup::SharedPtr group = nullptr)
  {
    (void)group;
    auto period_ns = std::chrono::duration_cast<std::chrono::nanoseconds>(period);
    auto timer = std::make_shared<rclcpp::WallTimer<CallbackT>>(period_ns, std::move(callback), core_);
    auto & reg = ::rhi_fake::detail::ros_registry();
    std::lock_guard<std::mutex> lock(reg.mutex);
    for (auto it = reg.timers.begin(); it != reg.timers.end(); ) {
      if (it->expired()) {
        it = reg.timers.erase(it);
      } else {
        ++it;
      }
    }
    reg.timers.push_back(std::weak_ptr<rclcpp::TimerBase>(timer));
    return timer;
  }

  // ---------------------------------------------------------------- services
  // rclcpp 16 (Humble) takes an rmw_qos_profile_t; 21+ adds rclcpp::QoS (default ServicesQoS()) and
  // deprecates the rmw_qos_profile_t overloads (28, Jazzy); 29+ (Kilted, Rolling) removed them.

#if RHI_FAKE_RCLCPP_MAJOR < 21
  template<typename ServiceT>
  typename rclcpp::Client<ServiceT>::SharedPtr
  create_client(
    const std::string & service_name,
    const rmw_qos_profile_t & qos_profile = rmw_qos_profile_services_default,
    rclcpp::CallbackGroup::SharedPtr group = nullptr)
  {
    return rhi_create_client<ServiceT>(service_name, qos_profile, std::move(group));
  }

  template<typename ServiceT, typename CallbackT>
  typename rclcpp::Service<ServiceT>::SharedPtr
  create_service(
    const std::string & service_name,
    CallbackT && callback,
    const rmw_qos_profile_t & qos_profile = rmw_qos_profile_services_default,
    rclcpp::CallbackGroup::SharedPtr group = nullptr)
  {
    return rhi_create_service<ServiceT>(
      service_name, std::forward<CallbackT>(callback), qos_profile, std::move(group));
  }
#else
#if RHI_FAKE_RCLCPP_MAJOR < 29
  template<typename ServiceT>
  [[deprecated("use rclcpp::QoS instead of rmw_qos_profile_t")]]
  typename rclcpp::Client<ServiceT>::SharedPtr
  create_client(
    const std::string & service_name,
    const rmw_qos_profile_t & qos_profile,
    rclcpp::CallbackGroup::SharedPtr group = nullptr)
  {
    return rhi_create_client<ServiceT>(service_name, qos_profile, std::move(group));
  }

  template<typename ServiceT, typename CallbackT>
  [[deprecated("use rclcpp::QoS instead of rmw_qos_profile_t")]]
  typename rclcpp::Service<ServiceT>::SharedPtr
  create_service(
    const std::string & service_name,
    CallbackT && callback,
    const rmw_qos_profile_t & qos_profile,
    rclcpp::CallbackGroup::SharedPtr group = nullptr)
  {
    return rhi_create_service<ServiceT>(
      service_name, std::forward<CallbackT>(callback), qos_profile, std::move(group));
  }
#endif

  template<typename ServiceT>
  typename rclcpp::Client<ServiceT>::SharedPtr
  create_client(
    const std::string & service_name,
    const rclcpp::QoS & qos = rclcpp::ServicesQoS(),
    rclcpp::CallbackGroup::SharedPtr group = nullptr)
  {
    return rhi_create_client<ServiceT>(service_name, qos.get_rmw_qos_profile(), std::move(group));
  }

  template<typename ServiceT, typename CallbackT>
  typename rclcpp::Service<ServiceT>::SharedPtr
  create_service(
    const std::string & service_name,
    CallbackT && callback,
    const rclcpp::QoS & qos = rclcpp::ServicesQoS(),
    rclcpp::CallbackGroup::SharedPtr group = nullptr)
  {
    return rhi_create_service<ServiceT>(
      service_name, std::forward<CallbackT>(callback), qos.get_rmw_qos_profile(), std::move(group));
  }
#endif

  // ---------------------------------------------------------------- parameters

  using OnSetParametersCallbackHandle = rclcpp::node_interfaces::OnSetParametersCallbackHandle;

  const rclcpp::ParameterValue & declare_parameter(
    const std::string & name, const rclcpp::ParameterValue & default_value,
    const rcl_interfaces::msg::ParameterDescriptor & parameter_descriptor =
    rcl_interfaces::msg::ParameterDescriptor(),
    bool ignore_override = false)
  {
    (void)parameter_descriptor;
    (void)ignore_override;
    std::vector<OnSetParametersCallbackHandle::SharedPtr> callbacks;
    {
      std::lock_guard<std::mutex> lock(parameters_mutex_);
      if (parameters_.count(name) != 0U) {
        throw rclcpp::exceptions::ParameterAlreadyDeclaredException(
                "parameter '" + name + "' has already been declared");
      }
      callbacks = live_callbacks();
    }
    // Declaring runs the on-set callbacks, as rclcpp does; a refusal throws.
    const std::vector<rclcpp::Parameter> parameters{rclcpp::Parameter(name, default_value)};
    for (const auto & handle : callbacks) {
      const auto result = handle->callback(parameters);
      if (!result.successful) {
        throw rclcpp::exceptions::InvalidParameterValueException(
                "parameter '" + name + "' could not be set: " + result.reason);
      }
    }
    std::lock_guard<std::mutex> lock(parameters_mutex_);
    return parameters_[name] = default_value;
  }

  template<typename ParameterT>
  auto declare_parameter(
    const std::string & name, const ParameterT & default_value,
    const rcl_interfaces::msg::ParameterDescriptor & parameter_descriptor =
    rcl_interfaces::msg::ParameterDescriptor(),
    bool ignore_override = false)
  {
    try {
      return this->declare_parameter(
        name, rclcpp::ParameterValue(default_value), parameter_descriptor,
        ignore_override).template get<ParameterT>();
    } catch (const ParameterTypeException & ex) {
      throw exceptions::InvalidParameterTypeException(name, ex.what());
    }
  }

  rclcpp::Parameter get_parameter(const std::string & name) const
  {
    std::lock_guard<std::mutex> lock(parameters_mutex_);
    const auto it = parameters_.find(name);
    if (it == parameters_.end()) {
      throw rclcpp::exceptions::ParameterNotDeclaredException(name);
    }
    return rclcpp::Parameter(name, it->second);
  }

  /// What `ros2 param set` reaches: the callbacks (newest first) may refuse, then the value is stored.
  rcl_interfaces::msg::SetParametersResult set_parameter(const rclcpp::Parameter & parameter)
  {
    rcl_interfaces::msg::SetParametersResult result;
    result.successful = true;
    std::vector<OnSetParametersCallbackHandle::SharedPtr> callbacks;
    {
      std::lock_guard<std::mutex> lock(parameters_mutex_);
      const auto it = parameters_.find(parameter.get_name());
      if (it == parameters_.end()) {
        throw rclcpp::exceptions::ParameterNotDeclaredException(parameter.get_name());
      }
      if (it->second.get_type() != parameter.get_type()) {
        result.successful = false;
        result.reason = "Wrong parameter type, parameter {" + parameter.get_name() + "} is of type {" +
          rclcpp::to_string(it->second.get_type()) + "}, setting it to {" +
          rclcpp::to_string(parameter.get_type()) + "} is not allowed.";
        return result;
      }
      callbacks = live_callbacks();
    }
    const std::vector<rclcpp::Parameter> parameters{parameter};
    for (const auto & handle : callbacks) {
      result = handle->callback(parameters);
      if (!result.successful) {
        return result;
      }
    }
    std::lock_guard<std::mutex> lock(parameters_mutex_);
    parameters_[parameter.get_name()] = parameter.get_parameter_value();
    return result;
  }

  [[nodiscard]] OnSetParametersCallbackHandle::SharedPtr add_on_set_parameters_callback(
    std::function<rcl_interfaces::msg::SetParametersResult(const std::vector<rclcpp::Parameter> &)>
    callback)
  {
    auto handle = std::make_shared<OnSetParametersCallbackHandle>();
    handle->callback = std::move(callback);
    std::lock_guard<std::mutex> lock(parameters_mutex_);
    on_set_callbacks_.push_back(handle);
    return handle;
  }

private:
  template<typename ServiceT>
  typename rclcpp::Client<ServiceT>::SharedPtr
  rhi_create_client(
    const std::string & service_name, const rmw_qos_profile_t & profile,
    rclcpp::CallbackGroup::SharedPtr group)
  {
    (void)group;   // the fake runs a node's callbacks mutually exclusively
    const rclcpp::QoS qos(rclcpp::QoSInitialization::from_rmw(profile), profile);
    const std::string name = ::rhi_fake::detail::expand_topic_name(service_name, *core_, true);
    auto client = std::make_shared<rclcpp::Client<ServiceT>>(core_, name, qos);
    std::shared_ptr<::rhi_fake::detail::ResponseSink> sink = client;
    auto & reg = ::rhi_fake::detail::ros_registry();
    std::lock_guard<std::mutex> lock(reg.mutex);
    for (auto it = reg.clients_by_id.begin(); it != reg.clients_by_id.end(); ) {
      if (it->second.expired()) {
        it = reg.clients_by_id.erase(it);
      } else {
        ++it;
      }
    }
    reg.clients_by_id[client->rhi_id()] = sink;
    auto & record = reg.services[name];
    ::rhi_fake::detail::prune_dead(record.clients);
    record.clients.push_back(
      ::rhi_fake::detail::make_endpoint(
        sink, qos, *core_, std::type_index(typeid(ServiceT)),
        rosidl_generator_traits::name<ServiceT>()));
    return client;
  }

  template<typename ServiceT, typename CallbackT>
  typename rclcpp::Service<ServiceT>::SharedPtr
  rhi_create_service(
    const std::string & service_name, CallbackT && callback, const rmw_qos_profile_t & profile,
    rclcpp::CallbackGroup::SharedPtr group)
  {
    (void)group;
    static_assert(
      rosidl_generator_traits::is_service<ServiceT>::value,
      "create_service<ServiceT>: ServiceT must be a ROS service type (<pkg>/srv/<name>.hpp)");
    rclcpp::AnyServiceCallback<ServiceT> any_callback;
    any_callback.set(std::forward<CallbackT>(callback));
    const rclcpp::QoS qos(rclcpp::QoSInitialization::from_rmw(profile), profile);
    const std::string name = ::rhi_fake::detail::expand_topic_name(service_name, *core_, true);
    auto service = std::make_shared<rclcpp::Service<ServiceT>>(core_, name, std::move(any_callback), qos);
    std::shared_ptr<::rhi_fake::detail::RequestSink> sink = service;
    auto & reg = ::rhi_fake::detail::ros_registry();
    {
      std::lock_guard<std::mutex> lock(reg.mutex);
      auto & record = reg.services[name];
      ::rhi_fake::detail::prune_dead(record.servers);
      record.servers.push_back(
        ::rhi_fake::detail::make_endpoint(
          sink, qos, *core_, std::type_index(typeid(ServiceT)),
          rosidl_generator_traits::name<ServiceT>()));
    }
    reg.graph_cv.notify_all();
    return service;
  }

  // The live on-set callbacks, newest first (parameters_mutex_ held).
  std::vector<OnSetParametersCallbackHandle::SharedPtr> live_callbacks() const
  {
    std::vector<OnSetParametersCallbackHandle::SharedPtr> out;
    for (auto weak = on_set_callbacks_.rbegin(); weak != on_set_callbacks_.rend(); ++weak) {
      if (auto handle = weak->lock()) {
        out.push_back(handle);
      }
    }
    return out;
  }

  mutable std::mutex parameters_mutex_;
  std::map<std::string, rclcpp::ParameterValue> parameters_;
  std::vector<std::weak_ptr<OnSetParametersCallbackHandle>> on_set_callbacks_;
  NodeOptions options_;
  rclcpp::Logger logger_;
  rclcpp::Clock::SharedPtr clock_;
  std::shared_ptr<::rhi_fake::detail::NodeCore> core_;
  node_interfaces::NodeBaseInterface::SharedPtr base_;
  node_interfaces::NodeClockInterface::SharedPtr clock_if_;
  node_interfaces::NodeLoggingInterface::SharedPtr logging_if_;
};

}  // namespace rclcpp

#endif  // RCLCPP__NODE_HPP_
