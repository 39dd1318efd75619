// rhi-gen test hooks: everything (hw facade, logs, plugins, ros, services, unitree), plus reset_all(). Test
// code only.
#pragma once

#include "rhi_fake/hw.hpp"
#include "rhi_fake/logs.hpp"
#include "rhi_fake/plugins.hpp"
#include "rhi_fake/ros.hpp"
#include "rhi_fake/services.hpp"
#include "rhi_fake/unitree.hpp"

namespace rhi_fake {

/// ros::reset() + unitree::reset() + logs::clear(). Call between tests, with no driver alive.
inline void reset_all()
{
  ros::reset();
  unitree::reset();
  logs::clear();
}

}  // namespace rhi_fake
