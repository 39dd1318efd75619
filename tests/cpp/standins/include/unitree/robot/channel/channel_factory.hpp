// rhi-gen test stand-in (not the real unitree_sdk2): unitree::robot::ChannelFactory.
// Same public API as the SDK header (Instance(), Init(domainId, networkInterface = ""),
// Init(configFileName = ""), Release(), CreateSendChannel / CreateRecvChannel). Creating a channel
// before Init() throws std::logic_error (the real SDK dereferences a null factory there).
// There is no DDS: a written message is kept per channel for the test
// (rhi_fake::unitree::last_written), and readers receive what the test delivers
// (rhi_fake::unitree::deliver), synchronously on the test's thread.
#ifndef __UT_ROBOT_SDK_CHANNEL_FACTORY_HPP__
#define __UT_ROBOT_SDK_CHANNEL_FACTORY_HPP__

#include <algorithm>
#include <cstdint>
#include <functional>
#include <iostream>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <typeindex>
#include <utility>

#include <unistd.h>

// The SDK's channel headers reach the thread headers through its DDS layer (the SDK's own G1
// examples use ThreadPtr / CreateRecurrentThreadEx / UT_CPU_ID_NONE, std::cout and sleep() after
// including only channel_publisher.hpp / channel_subscriber.hpp), so the stand-in does too.
#include <unitree/common/thread/recurrent_thread.hpp>
#include "rhi_fake/detail/unitree_core.hpp"

namespace unitree
{
namespace common
{

/// A topic channel: write side (Write) and/or read side (handler, ReadLatest).
template<typename MSG>
class DdsTopicChannel
{
public:
  DdsTopicChannel(
    std::string name, std::shared_ptr<::rhi_fake::detail::ChannelSlot<MSG>> slot,
    std::shared_ptr<::rhi_fake::detail::ReaderEndpoint> reader)
  : name_(std::move(name)), slot_(std::move(slot)), reader_(std::move(reader)) {}

  DdsTopicChannel(const DdsTopicChannel &) = delete;
  DdsTopicChannel & operator=(const DdsTopicChannel &) = delete;

  ~DdsTopicChannel()
  {
    if (reader_) {reader_->close();}
  }

  bool Write(const MSG & message, int64_t waitMicrosec = 0)
  {
    (void)waitMicrosec;
    if (!slot_) {return false;}
    std::lock_guard<std::mutex> lock(slot_->mutex);
    slot_->last = message;
    slot_->write_count++;
    slot_->has_value = true;
    if (slot_->observer) {
      slot_->observer(static_cast<const void *>(&message));
    }
    return true;
  }

  bool ReadLatest(MSG & message)
  {
    if (!reader_) {return false;}
    std::lock_guard<std::recursive_mutex> lock(reader_->mutex);
    if (!reader_->has_latest) {return false;}
    message = *static_cast<const MSG *>(reader_->latest.get());
    return true;
  }

  int64_t GetLastDataAvailableTime() const
  {
    if (!reader_) {return -1;}
    std::lock_guard<std::recursive_mutex> lock(reader_->mutex);
    return reader_->last_data_time_us;
  }

  const std::string & GetName() const {return name_;}

private:
  std::string name_;
  std::shared_ptr<::rhi_fake::detail::ChannelSlot<MSG>> slot_;
  std::shared_ptr<::rhi_fake::detail::ReaderEndpoint> reader_;
};

template<typename MSG>
using DdsTopicChannelPtr = std::shared_ptr<DdsTopicChannel<MSG>>;

}  // namespace common

namespace robot
{
template<typename MSG>
using Channel = unitree::common::DdsTopicChannel<MSG>;

template<typename MSG>
using ChannelPtr = unitree::common::DdsTopicChannelPtr<MSG>;

class ChannelFactory
{
public:
  static ChannelFactory * Instance()
  {
    static ChannelFactory inst;
    return &inst;
  }

  void Init(int32_t domainId, const std::string & networkInterface = "")
  {
    auto & reg = ::rhi_fake::detail::unitree_registry();
    std::lock_guard<std::mutex> lock(reg.mutex);
    reg.factory.init_count++;
    reg.factory.inited = true;
    reg.factory.by_config_file = false;
    reg.factory.domain_id = domainId;
    reg.factory.network_interface = networkInterface;
  }

  void Init(const std::string & configFileName = "")
  {
    auto & reg = ::rhi_fake::detail::unitree_registry();
    std::lock_guard<std::mutex> lock(reg.mutex);
    reg.factory.init_count++;
    reg.factory.inited = true;
    reg.factory.by_config_file = true;
    reg.factory.config_file = configFileName;
  }

  void Release()
  {
    auto & reg = ::rhi_fake::detail::unitree_registry();
    std::lock_guard<std::mutex> lock(reg.mutex);
    reg.factory.release_count++;
    reg.factory.inited = false;
  }

  template<typename MSG>
  ChannelPtr<MSG> CreateSendChannel(const std::string & name)
  {
    auto & reg = ::rhi_fake::detail::unitree_registry();
    std::lock_guard<std::mutex> lock(reg.mutex);
    require_init(reg, name);
    auto & record = reg.channels[name];
    if (!record.slot) {
      record.slot = std::make_shared<::rhi_fake::detail::ChannelSlot<MSG>>();
      record.type_name = typeid(MSG).name();
    } else if (record.slot->type != std::type_index(typeid(MSG))) {
      throw std::logic_error(
              "rhi_fake: channel '" + name + "' already written with another message type");
    }
    record.writers_created++;
    auto slot = std::static_pointer_cast<::rhi_fake::detail::ChannelSlot<MSG>>(record.slot);
    return std::make_shared<unitree::common::DdsTopicChannel<MSG>>(name, slot, nullptr);
  }

  template<typename MSG>
  ChannelPtr<MSG> CreateRecvChannel(
    const std::string & name, std::function<void(const void *)> callback, int32_t queuelen = 0)
  {
    auto reader = std::make_shared<::rhi_fake::detail::ReaderEndpoint>(
      std::type_index(typeid(MSG)), std::move(callback), queuelen);
    reader->latest = std::make_shared<MSG>();
    auto & reg = ::rhi_fake::detail::unitree_registry();
    std::lock_guard<std::mutex> lock(reg.mutex);
    require_init(reg, name);
    auto & record = reg.channels[name];
    if (!record.slot) {
      record.type_name = typeid(MSG).name();
    }
    for (auto it = record.readers.begin(); it != record.readers.end(); ) {
      if (it->expired()) {
        it = record.readers.erase(it);
      } else {
        ++it;
      }
    }
    record.readers.push_back(reader);
    return std::make_shared<unitree::common::DdsTopicChannel<MSG>>(name, nullptr, reader);
  }

  template<typename MSG>
  ChannelPtr<MSG> CreateRecvChannel(const std::string & name)
  {
    return CreateRecvChannel<MSG>(name, std::function<void(const void *)>(), 0);
  }

public:
  ~ChannelFactory() = default;

private:
  ChannelFactory() = default;

  static void require_init(::rhi_fake::detail::UnitreeRegistry & reg, const std::string & name)
  {
    if (!reg.factory.inited) {
      throw std::logic_error(
              "rhi_fake: channel '" + name + "' created before ChannelFactory::Instance()->Init() "
              "(the real SDK crashes here)");
    }
  }
};

}  // namespace robot
}  // namespace unitree

#endif  // __UT_ROBOT_SDK_CHANNEL_FACTORY_HPP__
