// rhi-gen test stand-in (not the real unitree_sdk2): unitree::robot::b2::MotionSwitcherClient.
// Fake behaviour (configure with rhi_fake::unitree::set_motion_mode and friends):
//  * CheckMode(form, name) writes the configured form/name (default: empty = no controller
//    active) and returns the configured code (default 0);
//  * ReleaseMode() returns the configured code (default 0) and, by default, clears the mode name
//    so a `while (CheckMode(form, name), !name.empty()) ReleaseMode();` loop terminates;
//  * calls are counted (rhi_fake::unitree::motion_switcher()).
#ifndef __UT_ROBOT_B2_MOTION_SWITCHER_CLIENT_HPP__
#define __UT_ROBOT_B2_MOTION_SWITCHER_CLIENT_HPP__

#include <cstdint>
#include <mutex>
#include <string>

#include <unitree/robot/client/client.hpp>
#include "rhi_fake/detail/unitree_core.hpp"

namespace unitree
{
namespace robot
{
namespace b2
{
class MotionSwitcherClient : public Client
{
public:
  explicit MotionSwitcherClient()
  : Client("motion_switcher", false)
  {
    auto & reg = ::rhi_fake::detail::unitree_registry();
    std::lock_guard<std::mutex> lock(reg.mutex);
    reg.motion.constructed++;
  }

  ~MotionSwitcherClient() = default;

  void Init() override
  {
    SetApiVersion("1.0.0.1");
    auto & reg = ::rhi_fake::detail::unitree_registry();
    std::lock_guard<std::mutex> lock(reg.mutex);
    reg.motion.init_calls++;
  }

  int32_t CheckMode(std::string & form, std::string & name)
  {
    auto & reg = ::rhi_fake::detail::unitree_registry();
    std::lock_guard<std::mutex> lock(reg.mutex);
    reg.motion.check_calls++;
    form = reg.motion.form;
    name = reg.motion.name;
    return reg.motion.check_result;
  }

  int32_t SelectMode(const std::string & nameOrAlias)
  {
    auto & reg = ::rhi_fake::detail::unitree_registry();
    std::lock_guard<std::mutex> lock(reg.mutex);
    reg.motion.name = nameOrAlias;
    return 0;
  }

  int32_t ReleaseMode()
  {
    auto & reg = ::rhi_fake::detail::unitree_registry();
    std::lock_guard<std::mutex> lock(reg.mutex);
    reg.motion.release_calls++;
    if (reg.motion.release_clears_mode) {
      reg.motion.name.clear();
      reg.motion.form.clear();
    }
    return reg.motion.release_result;
  }

  int32_t SetSilent(bool silent)
  {
    (void)silent;
    return 0;
  }

  int32_t GetSilent(bool & silent)
  {
    silent = false;
    return 0;
  }

protected:
  void OnSetTimeout(double seconds) override
  {
    auto & reg = ::rhi_fake::detail::unitree_registry();
    std::lock_guard<std::mutex> lock(reg.mutex);
    reg.motion.set_timeout_calls++;
    reg.motion.last_timeout_s = seconds;
  }
};

}  // namespace b2
}  // namespace robot
}  // namespace unitree

#endif  // __UT_ROBOT_B2_MOTION_SWITCHER_CLIENT_HPP__
