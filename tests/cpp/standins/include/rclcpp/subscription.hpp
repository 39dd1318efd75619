// rhi-gen test stand-in (not the real ROS 2 code): rclcpp::Subscription (ROS 2 Humble API subset).
//
// Callback signatures accepted by Node::create_subscription<MessageT>(topic, qos, callback), as
// deduced by rclcpp from the callable's single parameter (lambda, functor, std::function, function
// pointer, or std::bind of a member/free function):
//   void(const MessageT &)                         (also by value: void(MessageT))
//   void(std::unique_ptr<MessageT>)
//   void(std::shared_ptr<const MessageT>)          (= MessageT::ConstSharedPtr)
//   void(const std::shared_ptr<const MessageT> &)
//   void(std::shared_ptr<MessageT>)                (= MessageT::SharedPtr) -- DEPRECATED in Humble:
//       compiles with a -Wdeprecated-declarations warning, i.e. fails under -Werror, exactly like
//       /opt/ros/humble/include/rclcpp/rclcpp/any_subscription_callback.hpp.
// Anything else (MessageT &, const std::shared_ptr<MessageT> &, generic lambdas, two parameters)
// is rejected at compile time. The rclcpp::MessageInfo two-parameter forms are not implemented.
//
// Delivery (rhi_fake::ros::deliver) runs the callback synchronously on the calling thread while
// holding the node's callback mutex (a node's callbacks never overlap, like the default mutually
// exclusive callback group). Allocation per delivery:
//   const MessageT & / by value ............... none (by value copies the message, as in rclcpp)
//   shared_ptr<const MessageT> forms .......... none if the test delivers a shared_ptr; if it
//       delivers a const MessageT &, the fake copies into a pooled shared_ptr that it reuses
//       whenever the callback did not keep the previous one (first delivery allocates).
//   shared_ptr<MessageT> (deprecated) ......... pooled copy, as above
//   unique_ptr<MessageT> ...................... one allocation per delivery (ownership is handed over)
#ifndef RCLCPP__SUBSCRIPTION_HPP_
#define RCLCPP__SUBSCRIPTION_HPP_

#include <cstddef>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <tuple>
#include <type_traits>
#include <typeindex>
#include <utility>

#include "rclcpp/macros.hpp"
#include "rclcpp/qos.hpp"
#include "rclcpp/visibility_control.hpp"
#include "rosidl_runtime_cpp/traits.hpp"
#include "rhi_fake/detail/distro.hpp"
#include "rhi_fake/detail/function_traits.hpp"
#include "rhi_fake/detail/ros_core.hpp"

namespace rclcpp
{

class SubscriptionBase : public std::enable_shared_from_this<SubscriptionBase>
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS_NOT_COPYABLE(SubscriptionBase)

  virtual ~SubscriptionBase() = default;

  const char * get_topic_name() const {return topic_.c_str();}

  /// Live publishers (of any type) on this topic in the fake graph.
  size_t get_publisher_count() const
  {
    auto & reg = ::rhi_fake::detail::ros_registry();
    std::lock_guard<std::mutex> lock(reg.mutex);
    auto it = reg.topics.find(topic_);
    if (it == reg.topics.end()) {return 0;}
    size_t n = 0;
    for (const auto & e : it->second.publishers) {
      if (!e.owner.expired()) {++n;}
    }
    return n;
  }

  rclcpp::QoS get_actual_qos() const {return qos_;}

  /// Stand-in internal.
  std::type_index rhi_type() const {return type_;}

  /// Stand-in internal: deliver a message of the subscription's type (`owned` is a
  /// `const std::shared_ptr<const MessageT> *` or null).
  virtual void rhi_deliver_erased(const void * msg, const void * owned) = 0;

protected:
  SubscriptionBase(
    std::shared_ptr<::rhi_fake::detail::NodeCore> node, std::string topic,
    const rclcpp::QoS & qos, std::type_index type)
  : node_(std::move(node)), topic_(std::move(topic)), qos_(qos), type_(type) {}

  SubscriptionBase(const SubscriptionBase &) = delete;
  SubscriptionBase & operator=(const SubscriptionBase &) = delete;

  std::shared_ptr<::rhi_fake::detail::NodeCore> node_;
  std::string topic_;
  rclcpp::QoS qos_;
  std::type_index type_;
};

template<typename MessageT, typename AllocatorT = std::allocator<void>>
class Subscription : public SubscriptionBase
{
  static_assert(
    rosidl_generator_traits::is_message<MessageT>::value,
    "rclcpp::Subscription<MessageT>: MessageT must be a ROS message type");

public:
  using ROSMessageType = MessageT;
  RCLCPP_SMART_PTR_DEFINITIONS_NOT_COPYABLE(Subscription)

  virtual ~Subscription() = default;

  /// Stand-in internal: run the callback with one message. `owned` may be null.
  virtual void rhi_deliver(const MessageT & msg, const std::shared_ptr<const MessageT> * owned) = 0;

  void rhi_deliver_erased(const void * msg, const void * owned) final
  {
    rhi_deliver(
      *static_cast<const MessageT *>(msg),
      static_cast<const std::shared_ptr<const MessageT> *>(owned));
  }

protected:
  Subscription(
    std::shared_ptr<::rhi_fake::detail::NodeCore> node, std::string topic, const rclcpp::QoS & qos)
  : SubscriptionBase(std::move(node), std::move(topic), qos, std::type_index(typeid(MessageT))) {}
};

}  // namespace rclcpp

namespace rhi_fake {
namespace detail {

enum class CallbackKind
{
  ConstRef,
  UniquePtr,
  SharedConstPtr,
  ConstRefSharedConstPtr,
  SharedPtr,
};

template<typename MessageT, typename Arg>
struct callback_kind_of
{
  using M = MessageT;
  using Fn = std::function<void (Arg)>;
  static constexpr bool exact_const_ref = std::is_same<Arg, const M &>::value;
  static constexpr bool exact_unique = std::is_same<Arg, std::unique_ptr<M>>::value;
  static constexpr bool exact_shared_const = std::is_same<Arg, std::shared_ptr<const M>>::value;
  static constexpr bool exact_ref_shared_const =
    std::is_same<Arg, const std::shared_ptr<const M> &>::value;
  static constexpr bool exact_shared = std::is_same<Arg, std::shared_ptr<M>>::value;

  // Otherwise rclcpp assigns std::function<void(Arg)> into a std::variant of the supported
  // signatures, which compiles only if exactly one of them can be built from it.
  static constexpr bool v_const_ref = std::is_invocable<Fn &, const M &>::value;
  static constexpr bool v_unique = std::is_invocable<Fn &, std::unique_ptr<M>>::value;
  static constexpr bool v_shared_const = std::is_invocable<Fn &, std::shared_ptr<const M>>::value;
  static constexpr bool v_ref_shared_const =
    std::is_invocable<Fn &, const std::shared_ptr<const M> &>::value;
  static constexpr bool v_shared = std::is_invocable<Fn &, std::shared_ptr<M>>::value;
  static constexpr int viable =
    int(v_const_ref) + int(v_unique) + int(v_shared_const) + int(v_ref_shared_const) + int(v_shared);

  static constexpr bool exact =
    exact_const_ref || exact_unique || exact_shared_const || exact_ref_shared_const || exact_shared;
  static constexpr bool supported = exact || viable == 1;

  static constexpr CallbackKind value =
    exact_const_ref ? CallbackKind::ConstRef :
    exact_unique ? CallbackKind::UniquePtr :
    exact_shared_const ? CallbackKind::SharedConstPtr :
    exact_ref_shared_const ? CallbackKind::ConstRefSharedConstPtr :
    exact_shared ? CallbackKind::SharedPtr :
    v_const_ref ? CallbackKind::ConstRef :
    v_unique ? CallbackKind::UniquePtr :
    v_shared_const ? CallbackKind::SharedConstPtr :
    v_ref_shared_const ? CallbackKind::ConstRefSharedConstPtr :
    CallbackKind::SharedPtr;
};

template<typename MessageT, typename CallbackT>
struct subscription_callback_traits
{
  using traits = ft::of<CallbackT>;
  static_assert(
    traits::arity == 1,
    "rclcpp stand-in: a subscription callback takes exactly one parameter (the message); the "
    "(message, rclcpp::MessageInfo) forms are not implemented by the stand-in");
  using Arg = std::tuple_element_t<0, typename traits::arguments>;
  using kind_of = callback_kind_of<MessageT, Arg>;
  static_assert(
    kind_of::supported,
    "rclcpp: unsupported subscription callback signature; use void(const MessageT &), "
    "void(std::shared_ptr<const MessageT>), void(const std::shared_ptr<const MessageT> &) or "
    "void(std::unique_ptr<MessageT>)");
  static constexpr CallbackKind kind = kind_of::value;
};

// Humble deprecates void(std::shared_ptr<MessageT>) callbacks; Iron and later accept them again.
#if RHI_FAKE_RCLCPP_SHARED_PTR_CALLBACK_DEPRECATED
template<typename MessageT>
[[deprecated("use 'void(std::shared_ptr<const MessageT>)' instead")]]
inline void shared_ptr_callback_is_deprecated() {}
#else
template<typename MessageT>
inline void shared_ptr_callback_is_deprecated() {}
#endif

template<typename MessageT, typename AllocatorT, typename CallbackT, CallbackKind Kind>
class SubscriptionImpl final : public rclcpp::Subscription<MessageT, AllocatorT>
{
public:
  SubscriptionImpl(
    std::shared_ptr<NodeCore> node, std::string topic, const rclcpp::QoS & qos, CallbackT callback)
  : rclcpp::Subscription<MessageT, AllocatorT>(std::move(node), std::move(topic), qos),
    callback_(std::move(callback)) {}

  void rhi_deliver(const MessageT & msg, const std::shared_ptr<const MessageT> * owned) override
  {
    std::lock_guard<std::recursive_mutex> lock(this->node_->callback_mutex);
    if constexpr (Kind == CallbackKind::ConstRef) {
      (void)owned;
      callback_(msg);
    } else if constexpr (Kind == CallbackKind::UniquePtr) {
      (void)owned;
      callback_(std::make_unique<MessageT>(msg));
    } else if constexpr (
      Kind == CallbackKind::SharedConstPtr || Kind == CallbackKind::ConstRefSharedConstPtr)
    {
      if (owned != nullptr && *owned) {
        callback_(*owned);
      } else {
        std::shared_ptr<const MessageT> p = pooled(msg);
        callback_(p);
      }
    } else {
      std::shared_ptr<MessageT> p = pooled(msg);
      callback_(p);
    }
  }

private:
  // Reuse the last delivered object unless the callback kept a reference to it.
  std::shared_ptr<MessageT> pooled(const MessageT & msg)
  {
    if (pool_ && pool_.use_count() == 1) {
      *pool_ = msg;
    } else {
      pool_ = std::make_shared<MessageT>(msg);
    }
    return pool_;
  }

  CallbackT callback_;
  std::shared_ptr<MessageT> pool_;
};

}  // namespace detail
}  // namespace rhi_fake

#endif  // RCLCPP__SUBSCRIPTION_HPP_
