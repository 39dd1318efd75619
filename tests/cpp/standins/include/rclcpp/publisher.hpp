// rhi-gen test stand-in (not the real ROS 2 code): rclcpp::Publisher (ROS 2 Humble API subset).
// publish(const MessageT&) copy-assigns the message into one retained object per topic and
// bumps a counter -- no allocation once the retained object's vectors/strings have grown to
// size. Tests read it with rhi_fake::ros::last_published<MessageT>(topic). Publishing does not
// loop back to subscriptions of the same process.
#ifndef RCLCPP__PUBLISHER_HPP_
#define RCLCPP__PUBLISHER_HPP_

#include <cstddef>
#include <memory>
#include <mutex>
#include <string>
#include <type_traits>
#include <typeindex>
#include <utility>

#include "rclcpp/macros.hpp"
#include "rclcpp/qos.hpp"
#include "rclcpp/visibility_control.hpp"
#include "rosidl_runtime_cpp/traits.hpp"
#include "rhi_fake/detail/ros_core.hpp"

namespace rclcpp
{

class PublisherBase : public std::enable_shared_from_this<PublisherBase>
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS_NOT_COPYABLE(PublisherBase)

  virtual ~PublisherBase() = default;

  const char * get_topic_name() const {return topic_.c_str();}

  /// Live subscriptions (of any type) on this topic in the fake graph.
  size_t get_subscription_count() const
  {
    auto & reg = ::rhi_fake::detail::ros_registry();
    std::lock_guard<std::mutex> lock(reg.mutex);
    auto it = reg.topics.find(topic_);
    if (it == reg.topics.end()) {return 0;}
    size_t n = 0;
    for (const auto & e : it->second.subscriptions) {
      if (!e.owner.expired()) {++n;}
    }
    return n;
  }

  size_t get_intra_process_subscription_count() const {return 0;}

  rclcpp::QoS get_actual_qos() const {return qos_;}

protected:
  PublisherBase(
    std::shared_ptr<::rhi_fake::detail::NodeCore> node, std::string topic, const rclcpp::QoS & qos)
  : node_(std::move(node)), topic_(std::move(topic)), qos_(qos) {}

  PublisherBase(const PublisherBase &) = delete;
  PublisherBase & operator=(const PublisherBase &) = delete;

  std::shared_ptr<::rhi_fake::detail::NodeCore> node_;
  std::string topic_;
  rclcpp::QoS qos_;
};

template<typename MessageT, typename AllocatorT = std::allocator<void>>
class Publisher : public PublisherBase
{
  static_assert(
    rosidl_generator_traits::is_message<MessageT>::value,
    "rclcpp::Publisher<MessageT>: MessageT must be a ROS message type");

public:
  using ROSMessageType = MessageT;
  RCLCPP_SMART_PTR_DEFINITIONS(Publisher<MessageT, AllocatorT>)

  /// Stand-in internal: created by Node::create_publisher only.
  Publisher(
    std::shared_ptr<::rhi_fake::detail::NodeCore> node, std::string topic,
    const rclcpp::QoS & qos, std::shared_ptr<::rhi_fake::detail::TopicSlot<MessageT>> slot)
  : PublisherBase(std::move(node), std::move(topic), qos), slot_(std::move(slot)) {}

  virtual ~Publisher() = default;

  /// Publish a message (exact message type only, as with rclcpp's templated overload).
  template<typename T>
  std::enable_if_t<
    rosidl_generator_traits::is_message<T>::value && std::is_same<T, MessageT>::value>
  publish(const T & msg)
  {
    std::lock_guard<std::mutex> lock(slot_->mutex);
    slot_->last = msg;
    slot_->count++;
    slot_->has_value = true;
    if (slot_->observer) {
      slot_->observer(static_cast<const void *>(&slot_->last));
    }
  }

  void publish(std::unique_ptr<MessageT, std::default_delete<MessageT>> msg)
  {
    this->publish(*msg);
  }

private:
  std::shared_ptr<::rhi_fake::detail::TopicSlot<MessageT>> slot_;
};

}  // namespace rclcpp

#endif  // RCLCPP__PUBLISHER_HPP_
