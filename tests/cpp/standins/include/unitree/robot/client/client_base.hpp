// rhi-gen test stand-in (not the real unitree_sdk2): unitree::robot::ClientBase.
// SetTimeout has two overloads (int64_t microseconds, float seconds) as in the SDK, so a double
// argument such as SetTimeout(5.0) is ambiguous and does not compile -- write SetTimeout(5.0f).
#ifndef __UT_ROBOT_SDK_CLIENT_BASE_HPP__
#define __UT_ROBOT_SDK_CLIENT_BASE_HPP__

#include <cstdint>
#include <memory>
#include <string>

namespace unitree
{
namespace robot
{
const int64_t ROBOT_CLIENT_TIMEOUT = 1000000;

class ClientBase
{
public:
  explicit ClientBase(const std::string & name)
  : mName(name), mTimeout(ROBOT_CLIENT_TIMEOUT) {}
  virtual ~ClientBase() = default;

  virtual void Init() = 0;

  void SetTimeout(int64_t timeout) {mTimeout = timeout; OnSetTimeout(static_cast<double>(timeout) * 1e-6);}
  void SetTimeout(float timeout)
  {
    mTimeout = static_cast<int64_t>(timeout * 1e6f);
    OnSetTimeout(static_cast<double>(timeout));
  }

protected:
  virtual void OnSetTimeout(double seconds) {(void)seconds;}

  std::string mName;
  int64_t mTimeout;
};

using ClientBasePtr = std::shared_ptr<ClientBase>;

}  // namespace robot
}  // namespace unitree

#endif  // __UT_ROBOT_SDK_CLIENT_BASE_HPP__
