// rhi-gen test stand-in internals: which ROS 2 distribution this include folder stands for.
// The distro-independent stand-ins (tests/cpp/standins/include) branch on these macros where the
// real APIs differ; drivers must not use them (gate on hardware_interface/version.h instead).
#ifndef RHI_FAKE__DETAIL__DISTRO_HPP_
#define RHI_FAKE__DETAIL__DISTRO_HPP_

#define RHI_FAKE_DISTRO "jazzy"
// hardware_interface 4.46.0 (ros2_control branch of this distro)
#define RHI_FAKE_HI_MAJOR 4
// rclcpp 28
#define RHI_FAKE_RCLCPP_MAJOR 28
// void(std::shared_ptr<MessageT>) subscription callbacks are [[deprecated]] (Humble only)
#define RHI_FAKE_RCLCPP_SHARED_PTR_CALLBACK_DEPRECATED 0

#endif  // RHI_FAKE__DETAIL__DISTRO_HPP_
