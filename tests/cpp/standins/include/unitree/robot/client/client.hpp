// rhi-gen test stand-in (not the real unitree_sdk2): unitree::robot::Client (public part only).
#ifndef __UT_ROBOT_SDK_CLIENT_HPP__
#define __UT_ROBOT_SDK_CLIENT_HPP__

#include <cstdint>
#include <memory>
#include <string>

#include <unitree/robot/client/client_base.hpp>

namespace unitree
{
namespace robot
{
class Client : public ClientBase
{
public:
  explicit Client(const std::string & name, bool enableLease = false)
  : ClientBase(name), mEnableLease(enableLease) {}
  virtual ~Client() = default;

  const std::string & GetApiVersion() const {return mApiVersion;}

protected:
  void SetApiVersion(const std::string & apiVersion) {mApiVersion = apiVersion;}

private:
  bool mEnableLease;
  std::string mApiVersion;
};

using ClientPtr = std::shared_ptr<Client>;

}  // namespace robot
}  // namespace unitree

#endif  // __UT_ROBOT_SDK_CLIENT_HPP__
