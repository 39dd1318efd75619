// rhi-gen test stand-in (not the real unitree_sdk2): unitree::robot::ChannelSubscriber<MSG>.
// The handler receives `const void *` pointing at a MSG. In the fake it runs on the thread that
// calls rhi_fake::unitree::deliver(); CloseChannel() (or destroying the subscriber) waits for a
// running handler and guarantees no later call. queuelen is recorded, not simulated.
#ifndef __UT_ROBOT_SDK_CHANNEL_SUBSCRIBER_HPP__
#define __UT_ROBOT_SDK_CHANNEL_SUBSCRIBER_HPP__

#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include <unitree/robot/channel/channel_factory.hpp>

namespace unitree
{
namespace robot
{
template<typename MSG>
class ChannelSubscriber
{
public:
  explicit ChannelSubscriber(const std::string & channelName)
  : mChannelName(channelName), mQueueLen(0)
  {}

  explicit ChannelSubscriber(
    const std::string & channelName, const std::function<void(const void *)> & handler,
    int64_t queuelen = 0)
  : mChannelName(channelName), mQueueLen(queuelen), mHandler(handler)
  {}

  void InitChannel(const std::function<void(const void *)> & handler, int64_t queuelen = 0)
  {
    mHandler = handler;
    mQueueLen = queuelen;
    InitChannel();
  }

  void InitChannel()
  {
    if (mHandler) {
      mChannelPtr = ChannelFactory::Instance()->CreateRecvChannel<MSG>(
        mChannelName, mHandler, static_cast<int32_t>(mQueueLen));
    } else {
      mChannelPtr = ChannelFactory::Instance()->CreateRecvChannel<MSG>(mChannelName);
    }
  }

  void CloseChannel()
  {
    mChannelPtr.reset();
  }

  int64_t GetLastDataAvailableTime() const
  {
    if (mChannelPtr) {
      return mChannelPtr->GetLastDataAvailableTime();
    }
    return -1;
  }

  const std::string & GetChannelName() const
  {
    return mChannelName;
  }

  bool ReadLatest(MSG & message)
  {
    if (mChannelPtr) {
      return mChannelPtr->ReadLatest(message);
    }
    return false;
  }

  bool Read(MSG & message)
  {
    return ReadLatest(message);
  }

private:
  std::string mChannelName;
  int64_t mQueueLen;
  std::function<void(const void *)> mHandler;
  ChannelPtr<MSG> mChannelPtr;
};

template<typename MSG>
using ChannelSubscriberPtr = std::shared_ptr<ChannelSubscriber<MSG>>;

}  // namespace robot
}  // namespace unitree

#endif  // __UT_ROBOT_SDK_CHANNEL_SUBSCRIBER_HPP__
