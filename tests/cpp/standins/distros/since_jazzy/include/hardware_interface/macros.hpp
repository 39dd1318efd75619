// rhi-gen test stand-in (not the real ROS 2 code).
#ifndef HARDWARE_INTERFACE__MACROS_HPP_
#define HARDWARE_INTERFACE__MACROS_HPP_

#include <stdexcept>
#include <string>

#define THROW_ON_NULLPTR(pointer) \
  if (!pointer) { \
    throw std::runtime_error( \
            std::string(__PRETTY_FUNCTION__) + " failed. " #pointer " is null."); \
  }

#endif  // HARDWARE_INTERFACE__MACROS_HPP_
